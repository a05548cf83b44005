// Chapter 25's shader binding table layout (chapters/25_ray_tracing/
// binding_table.hpp), for devices other than lavapipe, whose numbers (handle
// 32, alignment 16, base 32) never make the padding show.

#include "../../chapters/25_ray_tracing/binding_table.hpp"

#include <catch2/catch_test_macros.hpp>

TEST_CASE("the binding table for handle 32, alignment 32, base 64 (the page's figure)",
          "[ray tracing]") {
    // Records of 32; ray generation rounded up to 64; two miss records, 64,
    // already a multiple; the hit table at 128; 160 bytes in all.
    const BindingTableLayout t = binding_table_layout(32, 32, 64);
    CHECK(t.record == 32);
    CHECK(t.raygen_size == 64);
    CHECK(t.miss_offset == 64);
    CHECK(t.miss_size == 64);
    CHECK(t.hit_offset == 128);
    CHECK(t.hit_size == 32);
    CHECK(t.size == 160);
}

TEST_CASE("the binding table pads records and tables: handle 48, alignment 16, base 64",
          "[ray tracing]") {
    // 48 is a multiple of 16, so a record is 48; ray generation 48 -> 64;
    // two miss records are 96 -> 128; the hit table starts at 64 + 128.
    const BindingTableLayout t = binding_table_layout(48, 16, 64);
    CHECK(t.record == 48);
    CHECK(t.raygen_size == 64);
    CHECK(t.miss_offset == 64);
    CHECK(t.miss_size == 128);
    CHECK(t.hit_offset == 192);
    CHECK(t.size == 240);
    // Every table starts at a multiple of the base, and the strides the
    // chapter passes are multiples of the handle alignment.
    CHECK(t.miss_offset % 64 == 0);
    CHECK(t.hit_offset % 64 == 0);
    CHECK(t.record % 16 == 0);
}

TEST_CASE("a handle that is not a multiple of its alignment is padded", "[ray tracing]") {
    // A made-up device: handle 20 bytes, alignment 32, base 32.
    const BindingTableLayout t = binding_table_layout(20, 32, 32);
    CHECK(t.record == 32);
    CHECK(t.raygen_size == 32);
    CHECK(t.miss_size == 64);
    CHECK(t.hit_offset == 96);
    CHECK(t.size == 128);
}

TEST_CASE("lavapipe's numbers give the layout chapter 25 prints", "[ray tracing]") {
    // "handles 32 bytes, records 32 (handle alignment 16), tables at
    // multiples of 32: ray generation at 0, miss at 32 (2 records), hit at
    // 96 (1 record), 128 bytes" (book/25_ray_tracing.md).
    const BindingTableLayout t = binding_table_layout(32, 16, 32);
    CHECK(t.record == 32);
    CHECK(t.miss_offset == 32);
    CHECK(t.hit_offset == 96);
    CHECK(t.size == 128);
}
