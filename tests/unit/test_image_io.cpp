#include "vkt/resources/image_io.hpp"

#include "vkt/core/check.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <filesystem>

using vkt::RgbaImage;

static RgbaImage solid(uint32_t w, uint32_t h, uint8_t r, uint8_t g, uint8_t b, uint8_t a = 255) {
    RgbaImage image{w, h, std::vector<uint8_t>(size_t{w} * h * 4)};
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        image.pixels[i] = r;
        image.pixels[i + 1] = g;
        image.pixels[i + 2] = b;
        image.pixels[i + 3] = a;
    }
    return image;
}

TEST_CASE("a PNG written and read back is the same picture", "[image]") {
    RgbaImage image{3, 2, {}};
    for (uint8_t i = 0; i < 24; ++i) image.pixels.push_back(uint8_t(i * 10));
    auto path = std::filesystem::temp_directory_path() / "vkt_test_roundtrip.png";
    vkt::write_png(path, image);
    RgbaImage back = vkt::read_png(path);
    CHECK(back.width == 3);
    CHECK(back.height == 2);
    CHECK(back.pixels == image.pixels);
    std::filesystem::remove(path);
}

TEST_CASE("reading a missing or corrupt PNG is an error", "[image]") {
    auto dir = std::filesystem::temp_directory_path();
    CHECK_THROWS_AS(vkt::read_png(dir / "vkt_no_such_file.png"), vkt::Error);
    auto bad = dir / "vkt_corrupt.png";
    {
        std::FILE* f = std::fopen(bad.string().c_str(), "wb");
        std::fputs("not a png", f);
        std::fclose(f);
    }
    CHECK_THROWS_AS(vkt::read_png(bad), vkt::Error);
    std::filesystem::remove(bad);
    CHECK_THROWS_AS(vkt::write_png(dir / "x.png", RgbaImage{2, 2, {1, 2, 3}}), vkt::Error);
}

TEST_CASE("identical pictures do not differ", "[image]") {
    auto d = vkt::compare_images(solid(4, 4, 10, 20, 30), solid(4, 4, 10, 20, 30), 24);
    CHECK(d.rmse == 0);
    CHECK(d.max_channel_difference == 0);
    CHECK(d.pixels_over_threshold == 0);
    CHECK(vkt::within(d, {}));
}

TEST_CASE("differences are measured over RGB, not alpha", "[image]") {
    // One channel off by 30 in every pixel: RMSE = sqrt(30^2 / 3) = 17.32.
    auto d =
        vkt::compare_images(solid(2, 2, 100, 100, 100, 0), solid(2, 2, 130, 100, 100, 255), 24);
    CHECK(d.rmse == Catch::Approx(17.3205).epsilon(1e-4));
    CHECK(d.max_channel_difference == 30);
    CHECK(d.pixels_over_threshold == 4);
    CHECK(d.fraction_over_threshold == 1.0);
    CHECK_FALSE(vkt::within(d, {}));
}

TEST_CASE("each half of the tolerance fails a picture on its own", "[image]") {
    const RgbaImage a = solid(100, 100, 50, 50, 50);
    // 25 pixels (0.25%) off by 30 in red: RMSE sqrt(25 * 900 / 30000) = 0.87,
    // under 2.0, but too many pixels beyond the threshold.
    RgbaImage few = a;
    for (int x = 0; x < 25; ++x) few.pixels[size_t(x) * 4] = 80;
    auto d = vkt::compare_images(a, few, 24);
    CHECK(d.rmse == Catch::Approx(0.866).epsilon(1e-3));
    CHECK(d.fraction_over_threshold == Catch::Approx(0.0025));
    CHECK_FALSE(vkt::within(d, {}));
    // 15 such pixels (0.15%) pass.
    RgbaImage fewer = a;
    for (int x = 0; x < 15; ++x) fewer.pixels[size_t(x) * 4] = 80;
    CHECK(vkt::within(vkt::compare_images(a, fewer, 24), {}));
    // Every channel off by 3: no pixel beyond the threshold, but RMSE 3.0.
    RgbaImage tinted = a;
    for (size_t i = 0; i < tinted.pixels.size(); ++i)
        if (i % 4 != 3) tinted.pixels[i] = 53;
    d = vkt::compare_images(a, tinted, 24);
    CHECK(d.pixels_over_threshold == 0);
    CHECK(d.rmse == Catch::Approx(3.0));
    CHECK_FALSE(vkt::within(d, {}));
}

TEST_CASE("the tolerance lets rounding through and catches a wrong pixel block", "[image]") {
    // Rounding: every other pixel one level up, the rest one down (bias 0,
    // each tile's median 1 or -1 at most).
    RgbaImage a = solid(100, 100, 50, 50, 50), b = a;
    for (size_t p = 0; p < b.pixels.size(); p += 4)
        for (size_t c = 0; c < 3; ++c) b.pixels[p + c] = uint8_t(50 + ((p / 4) % 2 ? 1 : -1));
    auto d = vkt::compare_images(a, b, 24);
    CHECK(d.max_bias == Catch::Approx(0.0));
    CHECK(d.max_tile_median == 1);
    CHECK(vkt::within(d, {}));
    RgbaImage c = a;  // a 5x5 block (0.25% of the pixels) entirely wrong
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) c.pixels[(y * 100 + x) * 4] = 255;
    d = vkt::compare_images(a, c, 24);
    CHECK(d.pixels_over_threshold == 25);
    CHECK_FALSE(vkt::within(d, {}));
}

TEST_CASE("a picture one level brighter everywhere is refused by its bias", "[image]") {
    // Every channel of every pixel +1: RMSE 1.0 and no pixel past 24, which
    // the first two limits allow, but a bias of 1.0 (a - b: -1 in size).
    RgbaImage a = solid(100, 100, 50, 50, 50), b = a;
    for (size_t i = 0; i < b.pixels.size(); ++i)
        if (i % 4 != 3) b.pixels[i] = 51;
    const auto d = vkt::compare_images(a, b, 24);
    CHECK(d.rmse == Catch::Approx(1.0));
    CHECK(d.max_bias == Catch::Approx(1.0));
    CHECK_FALSE(vkt::within(d, {}));
    // One channel only, in one pixel in 10: a bias of 0.1, past 0.08.
    RgbaImage e = a;
    for (size_t p = 0; p < 10000; p += 10) e.pixels[p * 4 + 2] = 51;
    CHECK(vkt::compare_images(a, e, 24).max_bias == Catch::Approx(0.1));
    CHECK_FALSE(vkt::within(vkt::compare_images(a, e, 24), {}));
}

TEST_CASE("a patch two levels off moves its tiles' medians; a moved edge does not", "[image]") {
    // 100 x 100: tiles of 16, the last row and column 4 wide. A 32 x 32 patch
    // two levels darker in green from (32, 48): its tiles' median is 2.
    RgbaImage a = solid(100, 100, 80, 80, 80), patch = a;
    for (int y = 48; y < 80; ++y)
        for (int x = 32; x < 64; ++x) patch.pixels[(y * 100 + x) * 4 + 1] = 78;
    auto d = vkt::compare_images(a, patch, 24);
    CHECK(d.max_tile_median == 2);
    CHECK(d.tile_x == 32);
    CHECK(d.tile_y == 48);
    CHECK(d.max_bias == Catch::Approx(2.0 * 1024 / 10000));
    CHECK_FALSE(vkt::within(d, {}));
    // An edge: a column of 100 pixels off by 200 moves no tile's median.
    RgbaImage edge = a;
    for (int y = 0; y < 100; ++y) edge.pixels[(y * 100 + 40) * 4] = 255;
    d = vkt::compare_images(a, edge, 24);
    CHECK(d.max_tile_median == 0);
    // The last, narrower column of tiles counts too: x 96..99.
    RgbaImage corner = a;
    for (int y = 0; y < 16; ++y)
        for (int x = 96; x < 100; ++x) corner.pixels[(y * 100 + x) * 4] = 90;
    d = vkt::compare_images(a, corner, 24);
    CHECK(d.max_tile_median == 10);
    CHECK(d.tile_x == 96);
}

TEST_CASE("the tolerances for other uses keep what they promise", "[image]") {
    const vkt::Tolerance across = vkt::Tolerance::across_devices();
    CHECK(across.max_rmse == 2.0);
    CHECK(across.max_bias == 1.0);
    CHECK(across.max_tile_median == 2);
    const vkt::Tolerance loose = vkt::Tolerance::loose(8, 24, 0.02);
    CHECK(loose.max_rmse == 8);
    CHECK(loose.max_fraction == 0.02);
    CHECK(loose.max_bias >= 255);
    CHECK(loose.max_tile_median >= 255);
}

TEST_CASE("pictures of different sizes cannot be compared", "[image]") {
    CHECK_THROWS_AS(vkt::compare_images(solid(2, 2, 0, 0, 0), solid(2, 3, 0, 0, 0), 24),
                    vkt::Error);
}

TEST_CASE("the difference image shows |a - b| four times brighter, opaque", "[image]") {
    RgbaImage d = vkt::difference_image(solid(1, 1, 10, 200, 0, 7), solid(1, 1, 20, 100, 0, 9));
    CHECK(d.pixels == std::vector<uint8_t>{40, 255, 0, 255});
}
