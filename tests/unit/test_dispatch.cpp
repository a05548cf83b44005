// Chapter 13's dispatch arithmetic (vkt/compute.hpp): how many workgroups
// cover n items, how many items one dispatch may cover under a device's
// limits, and the split of a large job into dispatches; and the std430
// layout of the particle, C++ against the compiled shader.
#include "../../chapters/13_compute/particle.hpp"
#include "spirv_reflect.hpp"
#include "vkt/check.hpp"
#include "vkt/compute.hpp"

#include <catch2/catch_test_macros.hpp>

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace {

// Only the limits max_items_per_dispatch reads.
VkPhysicalDeviceLimits limits(uint32_t max_groups_x, uint32_t max_range, uint32_t alignment) {
    VkPhysicalDeviceLimits l{};
    l.maxComputeWorkGroupCount[0] = max_groups_x;
    l.maxStorageBufferRange = max_range;
    l.minStorageBufferOffsetAlignment = alignment;
    return l;
}

}  // namespace

TEST_CASE("dispatch_count is ceil(n / group)", "[compute]") {
    // Multiples of the workgroup: exact.
    CHECK(vkt::dispatch_count(256, 256) == 1);
    CHECK(vkt::dispatch_count(65536, 256) == 256);
    CHECK(vkt::dispatch_count(1048576, 256) == 4096);
    CHECK(vkt::dispatch_count(16777216, 256) == 65536);
    // Not multiples: one more, partly idle, group.
    CHECK(vkt::dispatch_count(1, 256) == 1);
    CHECK(vkt::dispatch_count(255, 256) == 1);
    CHECK(vkt::dispatch_count(257, 256) == 2);
    CHECK(vkt::dispatch_count(1000, 256) == 4);  // 1024 invocations, 24 idle
    CHECK(vkt::dispatch_count(65537, 256) == 257);
    CHECK(vkt::dispatch_count(1000, 64) == 16);
    // Nothing to do: no groups. A group of one: one per item.
    CHECK(vkt::dispatch_count(0, 256) == 0);
    CHECK(vkt::dispatch_count(12345, 1) == 12345);
    // No overflow at the top of the range (n + group - 1 would wrap to 254).
    CHECK(vkt::dispatch_count(std::numeric_limits<uint64_t>::max(), 256) == (uint64_t(1) << 56));
    CHECK_THROWS_AS(vkt::dispatch_count(10, 0), std::invalid_argument);
    static_assert(vkt::dispatch_count(1000, 256) == 4);  // usable at compile time
}

TEST_CASE("max_items_per_dispatch: the smaller of the group-count and range limits", "[compute]") {
    // Lavapipe: 65,535 groups (16,776,960 items) but 128 MiB per descriptor,
    // 4,194,304 particles of 32 bytes: the range limits.
    CHECK(vkt::max_items_per_dispatch(limits(65535, 134217728, 16), 256, 32) == 4194304);
    // The smallest limits the specification allows (2^27 bytes, 65,535
    // groups, alignment up to 256): the same.
    CHECK(vkt::max_items_per_dispatch(limits(65535, 1u << 27, 256), 256, 32) == 4194304);
    // A range of 4 GiB - 1 with the minimum 65,535 groups: the group count
    // limits, and 16,777,216 particles need a second dispatch of one group.
    CHECK(vkt::max_items_per_dispatch(limits(65535, 0xffffffffu, 16), 256, 32) == 16776960);
    // A large GPU (2^31 - 1 groups, 4 GiB - 1 bytes): floor((2^32 - 1) / 32)
    // = 134,217,727, rounded down to whole workgroups.
    CHECK(vkt::max_items_per_dispatch(limits(0x7fffffffu, 0xffffffffu, 16), 256, 32) == 134217472);
    // Whole workgroups AND aligned offsets: items of 12 bytes, groups of 1,
    // alignment 64: a chunk must be a multiple of 16 items (192 bytes).
    CHECK(vkt::max_items_per_dispatch(limits(1000, 1000, 64), 1, 12) == 80);  // 83 -> 80
    // Not even one workgroup fits: an error, not zero.
    CHECK_THROWS_AS(vkt::max_items_per_dispatch(limits(65535, 4096, 16), 256, 32), vkt::Error);
    CHECK_THROWS_AS(vkt::max_items_per_dispatch(limits(0, 1u << 27, 16), 256, 32), vkt::Error);
}

TEST_CASE("split_dispatch: full chunks, then the rest", "[compute]") {
    SECTION("one dispatch when it fits") {
        const auto chunks = vkt::split_dispatch(65536, 256, 4194304);
        REQUIRE(chunks.size() == 1);
        CHECK(chunks[0].first == 0);
        CHECK(chunks[0].count == 65536);
        CHECK(chunks[0].groups == 256);
    }
    SECTION("16,777,216 particles on lavapipe: four dispatches of 4,194,304") {
        const auto chunks = vkt::split_dispatch(16777216, 256, 4194304);
        REQUIRE(chunks.size() == 4);
        for (size_t i = 0; i < 4; ++i) {
            CHECK(chunks[i].first == i * 4194304);
            CHECK(chunks[i].count == 4194304);
            CHECK(chunks[i].groups == 16384);
        }
    }
    SECTION("16,777,216 with only the group-count limit: 65,535 groups, then 1") {
        const auto chunks = vkt::split_dispatch(16777216, 256, 16776960);
        REQUIRE(chunks.size() == 2);
        CHECK(chunks[0].groups == 65535);
        CHECK(chunks[1].first == 16776960);
        CHECK(chunks[1].count == 256);
        CHECK(chunks[1].groups == 1);
    }
    SECTION("a last chunk that is not whole workgroups") {
        const auto chunks = vkt::split_dispatch(1000, 256, 512);
        REQUIRE(chunks.size() == 2);
        CHECK(chunks[0].count == 512);
        CHECK(chunks[0].groups == 2);
        CHECK(chunks[1].first == 512);
        CHECK(chunks[1].count == 488);
        CHECK(chunks[1].groups == 2);  // 512 invocations, 24 idle
    }
    SECTION("nothing") {
        CHECK(vkt::split_dispatch(0, 256, 512).empty());
    }
    SECTION("a chunk size that is not whole workgroups is a bug") {
        CHECK_THROWS_AS(vkt::split_dispatch(1000, 256, 300), std::invalid_argument);
        CHECK_THROWS_AS(vkt::split_dispatch(1000, 256, 0), std::invalid_argument);
    }
}

TEST_CASE("the particle's std430 layout matches the compiled compute shader", "[compute]") {
    const auto words = spirv::read(VKT_BINARY_DIR "/shaders/13_compute/simulate.comp.spv");
    const auto particle = spirv::offsets(words, "Particle");
    CHECK(particle.at("position") == offsetof(Particle, position));
    CHECK(particle.at("velocity") == offsetof(Particle, velocity));
    // The array of particles in the storage buffer: one Particle apart.
    CHECK(spirv::struct_members(words, "Particles").at("particles").array_stride ==
          sizeof(Particle));
}
