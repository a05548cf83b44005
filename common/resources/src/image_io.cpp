#include "vkt/resources/image_io.hpp"

#include "vkt/core/check.hpp"

#include <png.h>

#include <algorithm>
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
        throw Error("cannot write " + path.string() + ": " + png.message);
}

RgbaImage read_png(const std::filesystem::path& path) {
    return load_image_file(path);
}

ImageDifference compare_images(const RgbaImage& a, const RgbaImage& b, int threshold) {
    if (a.width != b.width || a.height != b.height)
        throw Error("images differ in size: " + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                    std::to_string(b.height));
    ImageDifference out;
    double sum_squares = 0;
    const size_t pixel_count = size_t{a.width} * a.height;
    for (size_t p = 0; p < pixel_count; ++p) {
        int worst = 0;
        for (size_t c = 0; c < 3; ++c) {
            int d = std::abs(int(a.pixels[p * 4 + c]) - int(b.pixels[p * 4 + c]));
            sum_squares += double(d) * d;
            worst = std::max(worst, d);
        }
        out.max_channel_difference = std::max(out.max_channel_difference, worst);
        if (worst > threshold) ++out.pixels_over_threshold;
    }
    if (pixel_count > 0) {
        out.rmse = std::sqrt(sum_squares / double(pixel_count * 3));
        out.fraction_over_threshold = double(out.pixels_over_threshold) / double(pixel_count);
    }
    return out;
}

bool within(const ImageDifference& difference, const Tolerance& tolerance) {
    return difference.rmse <= tolerance.max_rmse &&
           difference.fraction_over_threshold <= tolerance.max_fraction;
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
