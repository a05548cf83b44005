// vkt/resources/procedural_texture.hpp (chapter 15): the textures are deterministic,
// distinct, and have the texels worked out by hand below.

#include "vkt/core/check.hpp"
#include "vkt/resources/procedural_texture.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <array>

namespace {

std::array<int, 4> texel(const vkt::RgbaImage& image, uint32_t x, uint32_t y) {
    const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * 4];
    return {p[0], p[1], p[2], p[3]};
}

}  // namespace

TEST_CASE("procedural textures are the same bytes every time", "[procedural_texture]") {
    for (uint32_t index : {0u, 5u, 47u, 95u}) {
        const vkt::RgbaImage a = vkt::procedural_texture(index, 64);
        const vkt::RgbaImage b = vkt::procedural_texture(index, 64);
        CHECK(a.width == 64);
        CHECK(a.height == 64);
        REQUIRE(a.pixels.size() == 64u * 64u * 4u);
        CHECK(a.pixels == b.pixels);
    }
}

TEST_CASE("the 96 procedural textures all differ, then repeat", "[procedural_texture]") {
    std::vector<vkt::RgbaImage> all;
    for (uint32_t i = 0; i < vkt::procedural_texture_variety; ++i)
        all.push_back(vkt::procedural_texture(i, 64));
    for (size_t i = 0; i < all.size(); ++i)
        for (size_t j = i + 1; j < all.size(); ++j) {
            INFO("textures " << i << " and " << j);
            CHECK(all[i].pixels != all[j].pixels);
        }
    CHECK(vkt::procedural_texture(96 + 7, 64).pixels == all[7].pixels);
}

TEST_CASE("procedural textures: texels worked out by hand", "[procedural_texture]") {
    // 0: a red checker on the light ground, period 32 (squares of 16).
    const auto checker = vkt::procedural_texture(0, 64);
    CHECK(texel(checker, 0, 0) == std::array{220, 50, 40, 255});
    CHECK(texel(checker, 15, 15) == std::array{220, 50, 40, 255});
    CHECK(texel(checker, 16, 0) == std::array{235, 230, 215, 255});
    CHECK(texel(checker, 16, 16) == std::array{220, 50, 40, 255});
    // 12: the same checker on the dark ground.
    CHECK(texel(vkt::procedural_texture(12, 64), 16, 0) == std::array{35, 35, 45, 255});
    // 24: red checker again, period 64 / 4 = 16 (squares of 8).
    const auto fine = vkt::procedural_texture(24, 64);
    CHECK(texel(fine, 8, 0) == std::array{235, 230, 215, 255});
    CHECK(texel(fine, 16, 0) == std::array{220, 50, 40, 255});
    // 3: lime dots of radius 32 / 3 in cells of 32: a cell's centre (16, 16)
    // is lime; its corner (0, 0) is 16 * sqrt(2) = 22.6 texels away: ground.
    const auto dots = vkt::procedural_texture(3, 64);
    CHECK(texel(dots, 16, 16) == std::array{120, 190, 40, 255});
    CHECK(texel(dots, 26, 16) == std::array{120, 190, 40, 255});   // 10 < 10.67
    CHECK(texel(dots, 27, 16) == std::array{235, 230, 215, 255});  // 11 > 10.67
    CHECK(texel(dots, 0, 0) == std::array{235, 230, 215, 255});
    // 1: orange horizontal stripes 16 texels high.
    const auto stripes = vkt::procedural_texture(1, 64);
    CHECK(texel(stripes, 40, 15) == std::array{240, 140, 30, 255});
    CHECK(texel(stripes, 40, 16) == std::array{235, 230, 215, 255});
}

TEST_CASE("procedural_texture refuses sizes that are not powers of two from 16 to 1024",
          "[procedural_texture]") {
    using Catch::Matchers::ContainsSubstring;
    for (uint32_t size : {0u, 8u, 48u, 2048u})
        CHECK_THROWS_WITH(vkt::procedural_texture(0, size),
                          ContainsSubstring("size must be a power of two from 16 to 1024"));
    CHECK_NOTHROW(vkt::procedural_texture(0, 16));
}
