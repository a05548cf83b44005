#include "vkt/resources/image_io.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

namespace vkt {

// libpng's simplified API: one call, its errors as a message in the struct
// (no setjmp here: it keeps its own). The same library that reads them.
void write_png(const std::filesystem::path& path, const RgbaImage& image) {
    if (image.pixels.size() != size_t{image.width} * image.height * 4)
        throw Error("write_png: pixel data does not match " + std::to_string(image.width) + "x" +
                    std::to_string(image.height));
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    png.format = PNG_FORMAT_RGBA;
    if (!png_image_write_to_file(&png, path.string().c_str(), 0, image.pixels.data(), 0, nullptr))
        throw Error("cannot write " + shown_path(path) + ": " + png.message);
}

RgbaImage read_png(const std::filesystem::path& path) {
    return load_image_file(path);
}

namespace {

// The median of the values counted in `histogram` (a - b + 255, 511 bins):
// the middle one, the upper of the two middle ones for an even count.
int histogram_median(const std::array<uint32_t, 511>& histogram, uint32_t count) {
    uint32_t seen = 0;
    for (int i = 0; i < 511; ++i) {
        seen += histogram[size_t(i)];
        if (seen > count / 2) return i - 255;
    }
    return 0;
}

}  // namespace

ImageDifference compare_images(const RgbaImage& a, const RgbaImage& b, int threshold) {
    if (a.width != b.width || a.height != b.height)
        throw Error("images differ in size: " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    ImageDifference out;
    double sum_squares = 0;
    std::array<double, 3> sum{};
    const size_t pixel_count = size_t{a.width} * a.height;
    const auto difference = [&](size_t p, size_t c) {
        return int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c]);
    };
    for (size_t p = 0; p < pixel_count; ++p) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            const int d = difference(p, c);
            sum_squares += double(d) * d;
            sum[c] += d;
            worst = std::max(worst, std::abs(d));
        }
        out.max_channel_difference = std::max(out.max_channel_difference, worst);
        if (worst > threshold) ++out.pixels_over_threshold;
    }
    if (pixel_count == 0) return out;
    out.rmse = std::sqrt(sum_squares / double(pixel_count * 3));
    out.fraction_over_threshold = double(out.pixels_over_threshold) / double(pixel_count);
    for (size_t c = 0; c < 3; ++c)
        out.max_bias = std::max(out.max_bias, std::abs(sum[c] / double(pixel_count)));

    constexpr uint32_t tile = 16;
    for (uint32_t y0 = 0; y0 < a.height; y0 += tile)
        for (uint32_t x0 = 0; x0 < a.width; x0 += tile) {
            const uint32_t x1 = std::min(a.width, x0 + tile), y1 = std::min(a.height, y0 + tile);
            for (size_t c = 0; c < 3; ++c) {
                std::array<uint32_t, 511> histogram{};
                for (uint32_t y = y0; y < y1; ++y)
                    for (uint32_t x = x0; x < x1; ++x) {
                        const int bin = difference(size_t{y} * a.width + x, c) + 255;  // 0..510
                        ++histogram[size_t(bin)];
                    }
                const int median = std::abs(histogram_median(histogram, (x1 - x0) * (y1 - y0)));
                if (median > out.max_tile_median) {
                    out.max_tile_median = median;
                    out.tile_x = x0;
                    out.tile_y = y0;
                }
            }
        }
    return out;
}

bool within(const ImageDifference& difference, const Tolerance& tolerance) {
    return difference.rmse <= tolerance.max_rmse &&
           difference.fraction_over_threshold <= tolerance.max_fraction &&
           difference.max_bias <= tolerance.max_bias &&
           difference.max_tile_median <= tolerance.max_tile_median;
}

RgbaImage difference_image(const RgbaImage& a, const RgbaImage& b) {
    RgbaImage out{a.width, a.height, std::vector<uint8_t>(a.pixels.size())};
    for (size_t i = 0; i < a.pixels.size(); ++i)
        out.pixels[i] =
            (i % 4 == 3)
                ? 255
                : uint8_t(std::min(255, 4 * std::abs(int(a.pixels[i]) - int(b.pixels[i]))));
    return out;
}

}  // namespace vkt
