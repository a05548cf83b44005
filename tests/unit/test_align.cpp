// vkt::align_up (chapter 07): rounding a size up to a power-of-two alignment.
#include "vkt/resources/align.hpp"

#include <catch2/catch_test_macros.hpp>

TEST_CASE("align_up rounds up to the next multiple of the alignment", "[align]") {
    CHECK(vkt::align_up(64, 128) == 128);
    CHECK(vkt::align_up(128, 128) == 128);
    CHECK(vkt::align_up(0, 128) == 0);
    for (VkDeviceSize size = 129; size <= 256; ++size) CHECK(vkt::align_up(size, 128) == 256);
    CHECK(vkt::align_up(257, 128) == 384);
}

TEST_CASE("align_up with alignment 1 changes nothing, and works at compile time", "[align]") {
    for (VkDeviceSize size = 0; size < 20; ++size) CHECK(vkt::align_up(size, 1) == size);
    static_assert(vkt::align_up(100, 64) == 128);
    static_assert(vkt::align_up(76, 256) == 256);  // one 07 object block on a 256-byte device
    CHECK(vkt::align_up(1, 256) == 256);
}
