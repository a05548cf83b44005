#pragma once
// Image files and picture comparison: decoding PNG and JPEG (chapter 09's
// textures, chapter 10's glTF images), screenshots (--screenshot), the golden
// image tests, and the difference image a failing test leaves behind.

#include "vkt/core/memory_budget.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace vkt {

struct RgbaImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> pixels;  // width * height * 4 bytes, rows top to bottom, R G B A
};

// Decodes a PNG (with libpng) or JPEG (with libjpeg-turbo) into 8-bit RGBA;
// `what` names the bytes in the message: "WHAT: cannot decode image: <reason>",
// the reason being "not a PNG or JPEG file", the decoder's own words (a bad
// checksum, a file that ends early, ...) or the size checks below. Grey,
// palette and RGB images arrive as RGBA, alpha 255 where the file has none;
// 16-bit PNG channels keep their high byte. No gamma is applied: the bytes
// are the file's. From its header, before anything is decoded, an image is
// refused if it is wider or taller than max_image_side, if what it would
// cost (image_memory_cost, plus a progressive JPEG's coefficients) does not
// fit what is left of `budget`, or if the file is too small to hold the
// pixels its header claims (a PNG: its rows / 1032, deflate's best; a
// Huffman-coded JPEG: a bit for every 8x8 block of its smallest component).
// What it will cost is charged to `budget` before the pixels are allocated.
RgbaImage decode_image(std::span<const uint8_t> bytes, const std::string& what,
                       MemoryBudget& budget);
// The same with a budget of its own, of default_max_memory (1 GiB).
RgbaImage decode_image(std::span<const uint8_t> bytes, const std::string& what);

// The same for a file: "cannot open FILE" (vkt::read_file) when it cannot be
// read, then decode_image's messages, naming the file. The file's bytes are
// charged to the budget too.
RgbaImage load_image_file(const std::filesystem::path& path, MemoryBudget& budget);
RgbaImage load_image_file(const std::filesystem::path& path);

// The largest side decode_image accepts: the most maxImageDimension2D that
// desktop GPUs offer (lavapipe's too); 16384 x 16384 RGBA8 is 1 GiB.
constexpr uint32_t max_image_side = 16384;

// What an image of width x height costs a chapter at its peak, in bytes: the
// decoded RGBA pixels, then a staging copy and the GPU image (memory of the
// machine's on lavapipe), each with every mip level (a chain adds a third:
// x 4/3). So width x height x 4 x (1 + 4/3 + 4/3), 11/3 of the pixels:
// 8192 x 8192 costs 939 MiB and fits the default 1 GiB of --max-memory;
// 16384 x 16384 costs 3755 MiB, enough to freeze a laptop with 8 GB: it must
// be refused before it is decoded.
uint64_t image_memory_cost(uint32_t width, uint32_t height);

// The size a PNG or JPEG says it has, from what comes before its pixel data
// (PNG: the chunks up to the first IDAT's type; JPEG: the markers up to the
// first scan). Nothing is decoded and no limit applied; the same errors as
// decode_image otherwise.
struct ImageSize {
    uint32_t width = 0, height = 0;
};
ImageSize read_image_size(std::span<const uint8_t> bytes, const std::string& what);

// Writes 8-bit RGBA as a PNG (libpng); throws Error naming the file.
void write_png(const std::filesystem::path& path, const RgbaImage& image);
// Screenshots and golden images: load_image_file, the one decoder for every
// picture the project reads.
RgbaImage read_png(const std::filesystem::path& path);

// How far two pictures of the same size are apart, over the R, G and B channels
// (alpha is not shown on screen, so it is not compared).
struct ImageDifference {
    double rmse = 0;                 // root mean square of the channel differences, 0..255
    int max_channel_difference = 0;  // the largest single channel difference, 0..255
    uint64_t pixels_over_threshold = 0;
    double fraction_over_threshold = 0;  // of all pixels
    // The mean of a - b per channel, the largest in size: a picture brighter
    // or tinted everywhere, even by less than a level, moves it.
    double max_bias = 0;
    // In each 16 x 16 tile (the last row and column of tiles may be smaller),
    // the median of a - b per channel; the largest in size, and where. A
    // wrong patch moves a tile's median; a moved edge, which touches a few of
    // its pixels, does not.
    int max_tile_median = 0;
    uint32_t tile_x = 0, tile_y = 0;  // the top-left pixel of that tile
};

// Both images must have the same size (throws Error otherwise).
ImageDifference compare_images(const RgbaImage& a, const RgbaImage& b, int threshold);

// The tolerance of the golden image tests, stated in README.md: a picture
// passes when its RMSE is at most max_rmse, at most max_fraction of its
// pixels differ by more than threshold in some channel, no channel's mean
// difference is larger than max_bias, and no tile's median difference is
// larger than max_tile_median. The numbers come from measurements
// (tests/unit/test_golden_mutants.cpp, and book/appendix_testing.md):
// lavapipe on two processors (AVX2 and AVX-512, LLVM 15) differs from itself
// by an RMSE of at most 0.15, a bias of at most 0.02 and a tile median of at
// most 1, over all 45 golden images; wrong pictures made from each golden
// (everything 2 % brighter or darker in linear light, a 32 x 32 patch 10 %
// brighter or darker, the hue turned 10 degrees, a shift by one pixel, a 3 x 3
// blur, red and blue swapped) each break at least one of the four limits.
// The RMSE and the 24-level threshold catch moved edges and missing objects;
// the bias catches 2 % in linear light where it moves as little as 0.1 of a
// level on average (a line drawing on a dark background); the tile median
// catches a patch off by 2 levels or more.
struct Tolerance {
    double max_rmse = 2.0;
    int threshold = 24;
    double max_fraction = 0.002;
    double max_bias = 0.08;
    int max_tile_median = 1;

    // Another implementation of Vulkan (a GPU against lavapipe's golden
    // image: scripts/gpu-check.sh): the NVIDIA H200's pictures differ from
    // lavapipe's by a bias of up to 0.79 (23's textured model: its sRGB
    // decoding and pow() round differently) and a tile median of up to 2
    // (09 without anisotropy: its texture filtering), so the bias and the
    // tile may move that far; the 2 % brightness mutants then pass on the
    // scenes where they move less (tests/unit/test_golden_mutants.cpp lists
    // them), the rest are still refused.
    static Tolerance across_devices() { return Tolerance{.max_bias = 1.0, .max_tile_median = 2}; }
    // No bias or tile limit: two ways of drawing that differ by design
    // (chapter 24's shadow map against its rays), judged by RMSE and the
    // fraction of pixels beyond the threshold alone.
    static Tolerance loose(double rmse, int threshold, double fraction) {
        return Tolerance{.max_rmse = rmse,
                         .threshold = threshold,
                         .max_fraction = fraction,
                         .max_bias = 255.0,
                         .max_tile_median = 255};
    }
};
bool within(const ImageDifference& difference, const Tolerance& tolerance);

// |a - b| per channel, scaled up 4x so that small differences are visible.
RgbaImage difference_image(const RgbaImage& a, const RgbaImage& b);

}  // namespace vkt
