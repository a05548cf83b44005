#pragma once
// PNG files and picture comparison: screenshots (--screenshot), the golden
// image tests, and the difference image a failing test leaves behind.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace vkt {

struct RgbaImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> pixels;  // width * height * 4 bytes, rows top to bottom, R G B A
};

void write_png(const std::filesystem::path& path, const RgbaImage& image);
RgbaImage read_png(const std::filesystem::path& path);

// How far two pictures of the same size are apart, over the R, G and B channels
// (alpha is not shown on screen, so it is not compared).
struct ImageDifference {
    double rmse = 0;                 // root mean square of the channel differences, 0..255
    int max_channel_difference = 0;  // the largest single channel difference, 0..255
    uint64_t pixels_over_threshold = 0;
    double fraction_over_threshold = 0;  // of all pixels
};

// Both images must have the same size (throws Error otherwise).
ImageDifference compare_images(const RgbaImage& a, const RgbaImage& b, int threshold);

// The tolerance of the golden image tests, stated in README.md: a picture
// passes when its RMSE is at most max_rmse and at most max_fraction of its
// pixels differ by more than threshold in some channel. This absorbs rounding
// differences between rasterisers but not a moved edge or a wrong colour.
struct Tolerance {
    double max_rmse = 2.0;
    int threshold = 24;
    double max_fraction = 0.002;
};
bool within(const ImageDifference& difference, const Tolerance& tolerance);

// |a - b| per channel, scaled up 4x so that small differences are visible.
RgbaImage difference_image(const RgbaImage& a, const RgbaImage& b);

}  // namespace vkt
