#include "vkt/resources/readback.hpp"

#include "vkt/core/check.hpp"

#include <catch2/catch_test_macros.hpp>

#include <vector>

TEST_CASE("read-back BGRA pixels become RGBA, alpha opaque", "[readback]") {
    const std::vector<uint8_t> bgra{10, 20, 30, 0, 1, 2, 3, 128};
    vkt::RgbaImage image = vkt::to_rgba(bgra.data(), {2, 1}, VK_FORMAT_B8G8R8A8_UNORM);
    CHECK(image.width == 2);
    CHECK(image.height == 1);
    CHECK(image.pixels == std::vector<uint8_t>{30, 20, 10, 255, 3, 2, 1, 255});
    CHECK(vkt::to_rgba(bgra.data(), {2, 1}, VK_FORMAT_B8G8R8A8_SRGB).pixels == image.pixels);
}

TEST_CASE("read-back RGBA pixels stay in order, alpha opaque", "[readback]") {
    const std::vector<uint8_t> rgba{10, 20, 30, 0};
    CHECK(vkt::to_rgba(rgba.data(), {1, 1}, VK_FORMAT_R8G8B8A8_SRGB).pixels ==
          std::vector<uint8_t>{10, 20, 30, 255});
}

TEST_CASE("read-back of other formats is refused", "[readback]") {
    const std::vector<uint8_t> pixels(8);
    CHECK_THROWS_AS(vkt::to_rgba(pixels.data(), {1, 1}, VK_FORMAT_R16G16B16A16_SFLOAT), vkt::Error);
}
