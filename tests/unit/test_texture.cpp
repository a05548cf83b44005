// vkt/resources/texture.hpp (chapter 09): mip counts, image decoding, the CPU mip filter.

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/resources/texture.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <filesystem>

using Catch::Matchers::ContainsSubstring;

namespace {

vkt::RgbaImage solid(uint32_t width, uint32_t height, std::initializer_list<uint8_t> rgba_rows) {
    vkt::RgbaImage image{width, height, std::vector<uint8_t>(rgba_rows)};
    REQUIRE(image.pixels.size() == size_t(width) * height * 4);
    return image;
}

std::vector<uint8_t> bytes_of(const std::filesystem::path& path) {
    std::vector<char> file = vkt::read_file(path);
    return {file.begin(), file.end()};
}

}  // namespace

TEST_CASE("mip_level_count is floor(log2(max(w, h))) + 1", "[texture]") {
    CHECK(vkt::mip_level_count(1024, 1024) == 11);
    CHECK(vkt::mip_level_count(1, 1) == 1);
    CHECK(vkt::mip_level_count(640, 480) == 10);  // 640 320 160 80 40 20 10 5 2 1
    CHECK(vkt::mip_level_count(1000, 1) == 10);
    CHECK(vkt::mip_level_count(1, 1000) == 10);
    CHECK(vkt::mip_level_count(256, 256) == 9);
    CHECK(vkt::mip_level_count(0, 0) == 0);
}

TEST_CASE("mip_extent halves, rounds down and stops at 1", "[texture]") {
    CHECK(vkt::mip_extent(640, 480, 0).width == 640);
    CHECK(vkt::mip_extent(640, 480, 3).width == 80);
    CHECK(vkt::mip_extent(640, 480, 3).height == 60);
    CHECK(vkt::mip_extent(640, 480, 7).width == 5);
    CHECK(vkt::mip_extent(640, 480, 7).height == 3);  // 480 >> 7 = 3.75, rounded down
    CHECK(vkt::mip_extent(640, 480, 9).width == 1);
    CHECK(vkt::mip_extent(640, 480, 9).height == 1);  // 480 >> 9 = 0, clamped to 1
}

TEST_CASE("decode_image reads back a PNG written by write_png", "[texture]") {
    const auto path = std::filesystem::path(VKT_BINARY_DIR) / "test_texture_roundtrip.png";
    vkt::RgbaImage original = solid(3, 2, {255, 0,  0,  255, 0,   255, 0,   255, 0, 0, 255, 255,  //
                                           10,  20, 30, 40,  128, 128, 128, 0,   1, 2, 3,   4});
    vkt::write_png(path, original);
    vkt::RgbaImage decoded = vkt::decode_image(bytes_of(path), "roundtrip");
    CHECK(decoded.width == 3);
    CHECK(decoded.height == 2);
    CHECK(decoded.pixels == original.pixels);
    // And the same through the file loader.
    CHECK(vkt::load_image_file(path).pixels == original.pixels);
    std::filesystem::remove(path);
}

TEST_CASE("decode_image refuses bytes that are no image, with a clear message", "[texture]") {
    const std::vector<uint8_t> garbage = {'n', 'o', 't', ' ', 'a', 'n',
                                          ' ', 'i', 'm', 'a', 'g', 'e'};
    CHECK_THROWS_AS(vkt::decode_image(garbage, "garbage.png"), vkt::Error);
    CHECK_THROWS_WITH(vkt::decode_image(garbage, "garbage.png"),
                      "garbage.png: cannot decode image: not a PNG or JPEG file");
    CHECK_THROWS_WITH(vkt::decode_image({}, "empty"),
                      ContainsSubstring("empty: cannot decode image"));
}

// A PNG that is only a header claiming 20000 x 100 pixels and the start of
// an empty pixel chunk (libpng reads up to there before it gives the size):
// refused before decoding. The header's CRC is right: libpng checks it.
TEST_CASE("decode_image refuses a picture larger than max_image_side", "[texture]") {
    const std::vector<uint8_t> header = {
        0x89, 'P',  'N',  'G',  '\r', '\n', 0x1a, '\n',  // signature
        0,    0,    0,    13,   'I',  'H',  'D',  'R',   // IHDR, 13 bytes
        0,    0,    0x4e, 0x20, 0,    0,    0,    100,   // 20000 x 100
        8,    6,    0,    0,    0,                       // 8-bit RGBA
        0x63, 0x8d, 0,    0x67,                          // CRC
        0,    0,    0,    0,    'I',  'D',  'A',  'T'};  // IDAT, 0 bytes
    CHECK_THROWS_WITH(vkt::decode_image(header, "huge.png"),
                      "huge.png: cannot decode image: it is 20000x100, larger than 16384x16384");
}

TEST_CASE("load_image_file names a missing file", "[texture]") {
    CHECK_THROWS_WITH(vkt::load_image_file("/no/such/dir/texture.png"),
                      ContainsSubstring("cannot open /no/such/dir/texture.png"));
}

// Worked by hand: sRGB 0 and 255 are linear 0 and 1. Two of each average to
// linear 0.5, which sRGB encodes as 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536,
// i.e. 187.52 of 255: 188. Averaging the stored values instead gives 127.5,
// 128, a visibly darker grey: that is why the sRGB path decodes first.
TEST_CASE("downsample_box averages 2x2 in linear light for sRGB data", "[texture]") {
    // One 2x2 image; per channel: R 0 0 255 255, G 0 255 255 255, B all 128,
    // A 0 255 255 255.
    vkt::RgbaImage image = solid(2, 2,
                                 {0, 0, 128, 0, 0, 255, 128, 255,  //
                                  255, 255, 128, 255, 255, 255, 128, 255});
    vkt::RgbaImage srgb = vkt::downsample_box(image, true);
    REQUIRE(srgb.width == 1);
    REQUIRE(srgb.height == 1);
    CHECK(int(srgb.pixels[0]) == 188);  // linear 0.5
    CHECK(int(srgb.pixels[1]) == 225);  // linear 0.75: 0.8808 -> 224.61
    CHECK(int(srgb.pixels[2]) == 128);  // equal values stay put
    CHECK(int(srgb.pixels[3]) == 191);  // alpha is linear: 765 / 4 = 191.25

    vkt::RgbaImage unorm = vkt::downsample_box(image, false);
    CHECK(int(unorm.pixels[0]) == 128);  // 510 / 4 = 127.5, rounded to nearest
    CHECK(int(unorm.pixels[1]) == 191);
    CHECK(int(unorm.pixels[2]) == 128);
    CHECK(int(unorm.pixels[3]) == 191);
}

TEST_CASE("generate_mips_cpu makes the whole chain of a 4x4 image", "[texture]") {
    // Four 2x2 quadrants: red, green / blue, white.
    const uint8_t r[4] = {255, 0, 0, 255}, g[4] = {0, 255, 0, 255}, b[4] = {0, 0, 255, 255},
                  w[4] = {255, 255, 255, 255};
    vkt::RgbaImage image{4, 4, {}};
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x) {
            const uint8_t* c = y < 2 ? (x < 2 ? r : g) : (x < 2 ? b : w);
            image.pixels.insert(image.pixels.end(), c, c + 4);
        }
    std::vector<vkt::RgbaImage> levels = vkt::generate_mips_cpu(image, true);
    REQUIRE(levels.size() == 3);
    CHECK(levels[0].pixels == image.pixels);
    // Level 1: each quadrant is uniform, so it comes back exactly.
    CHECK(levels[1].width == 2);
    CHECK(levels[1].pixels == std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255,  //
                                                   0, 0, 255, 255, 255, 255, 255, 255});
    // Level 2: each channel is 255 in two quadrants of four, linear 0.5: 188.
    CHECK(levels[2].width == 1);
    CHECK(levels[2].pixels == std::vector<uint8_t>{188, 188, 188, 255});
    // Averaging the stored values: 127.5, rounded to 128.
    CHECK(vkt::generate_mips_cpu(image, false)[2].pixels ==
          std::vector<uint8_t>{128, 128, 128, 255});
}

TEST_CASE("downsample_box halves odd and thin images down to 1x1", "[texture]") {
    // 3x1 -> 1x1: the box covers texels 0 and 1; the odd last column falls
    // outside it. (A linear blit samples the middle instead: odd sizes are
    // where the two ways differ.)
    vkt::RgbaImage thin = solid(3, 1, {0, 0, 0, 255, 100, 100, 100, 255, 9, 9, 9, 9});
    vkt::RgbaImage half = vkt::downsample_box(thin, false);
    CHECK(half.width == 1);
    CHECK(half.height == 1);
    CHECK(half.pixels == std::vector<uint8_t>{50, 50, 50, 255});
    CHECK(vkt::generate_mips_cpu(solid(1, 1, {1, 2, 3, 4}), true).size() == 1);
    CHECK_THROWS_AS(vkt::downsample_box(vkt::RgbaImage{}, true), vkt::Error);
}
