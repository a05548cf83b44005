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
    RgbaImage a = solid(100, 100, 50, 50, 50), b = a;
    for (auto& p : b.pixels) p = uint8_t(p + 1);  // everything off by one: rounding
    CHECK(vkt::within(vkt::compare_images(a, b, 24), {}));
    RgbaImage c = a;  // a 5x5 block (0.25% of the pixels) entirely wrong
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) c.pixels[(y * 100 + x) * 4] = 255;
    auto d = vkt::compare_images(a, c, 24);
    CHECK(d.pixels_over_threshold == 25);
    CHECK_FALSE(vkt::within(d, {}));
}

TEST_CASE("pictures of different sizes cannot be compared", "[image]") {
    CHECK_THROWS_AS(vkt::compare_images(solid(2, 2, 0, 0, 0), solid(2, 3, 0, 0, 0), 24),
                    vkt::Error);
}

TEST_CASE("the difference image shows |a - b| four times brighter, opaque", "[image]") {
    RgbaImage d = vkt::difference_image(solid(1, 1, 10, 200, 0, 7), solid(1, 1, 20, 100, 0, 9));
    CHECK(d.pixels == std::vector<uint8_t>{40, 255, 0, 255});
}
