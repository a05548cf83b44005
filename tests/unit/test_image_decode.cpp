// vkt/resources/image_io.hpp: decode_image with libpng and libjpeg-turbo.
// Every kind of PNG arrives as the exact RGBA bytes of the file; a JPEG as
// RGBA close to what was encoded; a corrupt, truncated or oversized file of
// either kind as one vkt::Error naming it. The files are written here, with
// the same two libraries.

#include "vkt/core/check.hpp"
#include "vkt/resources/image_io.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <png.h>
// jpeglib.h uses size_t and FILE without including their headers.
#include <jpeglib.h>
#include <cstddef>
#include <cstdio>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <vector>

using Catch::Matchers::ContainsSubstring;
using Catch::Matchers::StartsWith;

namespace {

using Bytes = std::vector<uint8_t>;

// A PNG of `format` (PNG_FORMAT_*) from libpng's simplified writer; with a
// colormap, `pixels` are indices into it (a palette PNG).
Bytes png_of(uint32_t width, uint32_t height, uint32_t format, const void* pixels,
             const void* colormap = nullptr, uint32_t colormap_entries = 0) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = width;
    image.height = height;
    image.format = format;
    image.colormap_entries = colormap_entries;
    png_alloc_size_t size = 0;
    REQUIRE(png_image_write_get_memory_size(image, size, 0, pixels, 0, colormap));
    Bytes out(size);
    REQUIRE(png_image_write_to_memory(&image, out.data(), &size, 0, pixels, 0, colormap));
    out.resize(size);
    return out;
}

// A JPEG of 1 (grey) or 3 (RGB) components at quality 100; with `scans`,
// progressive, in that scan script.
Bytes jpeg_of(uint32_t width, uint32_t height, int components, const Bytes& pixels,
              const std::vector<jpeg_scan_info>& scans = {}) {
    jpeg_compress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);  // exits on error: these inputs are valid
    jpeg_create_compress(&info);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &buffer, &size);
    info.image_width = width;
    info.image_height = height;
    info.input_components = components;
    info.in_color_space = components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 100, TRUE);
    if (!scans.empty()) {
        info.scan_info = scans.data();
        info.num_scans = int(scans.size());
    }
    jpeg_start_compress(&info, TRUE);
    const size_t stride = size_t(width) * size_t(components);
    while (info.next_scanline < height) {
        auto* row = const_cast<JSAMPLE*>(pixels.data() + stride * info.next_scanline);
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    Bytes out(buffer, buffer + size);
    std::free(buffer);
    jpeg_destroy_compress(&info);
    return out;
}

// A smooth gradient, `channels` bytes a pixel (no wrap from 255 to 0 up to
// 16 x 16: a sharp edge is what JPEG keeps least exactly).
Bytes gradient(uint32_t width, uint32_t height, uint32_t channels) {
    Bytes pixels;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            for (uint32_t c = 0; c < channels; ++c)
                pixels.push_back(uint8_t((x * 8 + y * 4 + c * 32) & 0xff));
    return pixels;
}

// Where `marker` (a PNG chunk type, or a JPEG marker) first appears.
size_t find(const Bytes& bytes, std::initializer_list<uint8_t> marker) {
    auto at = std::search(bytes.begin(), bytes.end(), marker.begin(), marker.end());
    REQUIRE(at != bytes.end());
    return size_t(at - bytes.begin());
}

}  // namespace

TEST_CASE("decode_image gives every kind of PNG as the file's exact RGBA", "[image_decode]") {
    // Grey, grey + alpha, RGB: channels repeated, alpha 255 where none.
    const uint8_t grey[4] = {0, 85, 170, 255};
    CHECK(vkt::decode_image(png_of(2, 2, PNG_FORMAT_GRAY, grey), "grey.png").pixels ==
          Bytes{0, 0, 0, 255, 85, 85, 85, 255, 170, 170, 170, 255, 255, 255, 255, 255});
    const uint8_t grey_alpha[4] = {10, 20, 30, 40};
    CHECK(vkt::decode_image(png_of(2, 1, PNG_FORMAT_GA, grey_alpha), "ga.png").pixels ==
          Bytes{10, 10, 10, 20, 30, 30, 30, 40});
    const uint8_t rgb[6] = {1, 2, 3, 4, 5, 6};
    CHECK(vkt::decode_image(png_of(2, 1, PNG_FORMAT_RGB, rgb), "rgb.png").pixels ==
          Bytes{1, 2, 3, 255, 4, 5, 6, 255});
    // A palette, without and with transparency (a tRNS chunk).
    const uint8_t indices[3] = {2, 0, 1};
    const uint8_t palette_rgb[9] = {10, 20, 30, 40, 50, 60, 70, 80, 90};
    CHECK(vkt::decode_image(png_of(3, 1, PNG_FORMAT_RGB_COLORMAP, indices, palette_rgb, 3),
                            "palette.png")
              .pixels == Bytes{70, 80, 90, 255, 10, 20, 30, 255, 40, 50, 60, 255});
    const uint8_t palette_rgba[12] = {10, 20, 30, 0, 40, 50, 60, 128, 70, 80, 90, 255};
    CHECK(vkt::decode_image(png_of(3, 1, PNG_FORMAT_RGBA_COLORMAP, indices, palette_rgba, 3),
                            "palette_alpha.png")
              .pixels == Bytes{70, 80, 90, 255, 10, 20, 30, 0, 40, 50, 60, 128});
    // 16 bits a channel: the high byte, no gamma applied (the file says linear).
    const uint16_t deep[2] = {0x1234, 0xfedc};
    CHECK(vkt::decode_image(png_of(2, 1, PNG_FORMAT_LINEAR_Y, deep), "deep.png").pixels ==
          Bytes{0x12, 0x12, 0x12, 255, 0xfe, 0xfe, 0xfe, 255});
}

TEST_CASE("decode_image gives a JPEG as RGBA close to what was encoded", "[image_decode]") {
    const Bytes rgb = gradient(16, 8, 3);
    for (const bool progressive : {false, true}) {
        // libjpeg's own progressive script has about ten scans.
        const std::vector<jpeg_scan_info> dc_then_bands = {{3, {0, 1, 2, 0}, 0, 0, 0, 0},
                                                           {1, {0}, 1, 63, 0, 0},
                                                           {1, {1}, 1, 63, 0, 0},
                                                           {1, {2}, 1, 63, 0, 0}};
        const Bytes file =
            jpeg_of(16, 8, 3, rgb, progressive ? dc_then_bands : std::vector<jpeg_scan_info>{});
        const vkt::RgbaImage image = vkt::decode_image(file, "gradient.jpg");
        REQUIRE(image.width == 16);
        REQUIRE(image.height == 8);
        int worst = 0;
        for (size_t p = 0; p < 16 * 8; ++p) {
            for (size_t c = 0; c < 3; ++c)
                worst =
                    std::max(worst, std::abs(int(image.pixels[p * 4 + c]) - int(rgb[p * 3 + c])));
            CHECK(image.pixels[p * 4 + 3] == 255);
        }
        CHECK(worst <= 8);  // quality 100 and chroma subsampling: a few levels
    }
    // A grey JPEG: the same value in R, G and B.
    const vkt::RgbaImage grey = vkt::decode_image(jpeg_of(8, 8, 1, gradient(8, 8, 1)), "grey.jpg");
    for (size_t p = 0; p < 64; ++p) {
        CHECK(grey.pixels[p * 4] == grey.pixels[p * 4 + 1]);
        CHECK(grey.pixels[p * 4] == grey.pixels[p * 4 + 2]);
    }
}

TEST_CASE("decode_image refuses a corrupt PNG, naming it", "[image_decode]") {
    const Bytes file = png_of(8, 8, PNG_FORMAT_RGBA, gradient(8, 8, 4).data());
    const size_t idat = find(file, {'I', 'D', 'A', 'T'});
    // A byte of the compressed pixels: zlib finds it before the checksum.
    Bytes data = file;
    data[idat + 6] ^= 0x55;
    CHECK_THROWS_WITH(vkt::decode_image(data, "corrupt.png"),
                      StartsWith("corrupt.png: cannot decode image: its compressed pixel data "
                                 "(IDAT) is corrupt ("));
    // The chunk's checksum (the last 4 bytes before the next chunk, IEND).
    Bytes crc = file;
    crc[find(file, {'I', 'E', 'N', 'D'}) - 5] ^= 0x55;
    CHECK_THROWS_WITH(vkt::decode_image(crc, "corrupt.png"),
                      "corrupt.png: cannot decode image: its pixel data (IDAT) is damaged: its "
                      "checksum (CRC) does not match its bytes");
}

TEST_CASE("decode_image refuses a truncated PNG", "[image_decode]") {
    const Bytes file = png_of(8, 8, PNG_FORMAT_RGBA, gradient(8, 8, 4).data());
    // Cut inside the pixel data, and just before the end marker.
    const Bytes halves[2] = {
        Bytes(file.begin(), file.begin() + long(find(file, {'I', 'D', 'A', 'T'})) + 10),
        Bytes(file.begin(), file.end() - 12)};
    for (const Bytes& cut : halves)
        CHECK_THROWS_WITH(vkt::decode_image(cut, "cut.png"),
                          "cut.png: cannot decode image: the file ends early");
}

TEST_CASE("decode_image refuses a corrupt JPEG, naming it", "[image_decode]") {
    Bytes file = jpeg_of(16, 8, 3, gradient(16, 8, 3));
    // The frame header (SOF0): length, then the sample precision, 8.
    file[find(file, {0xff, 0xc0}) + 4] = 7;
    CHECK_THROWS_WITH(vkt::decode_image(file, "corrupt.jpg"),
                      "corrupt.jpg: cannot decode image: Unsupported JPEG data precision 7");
    // A file that is only the start-of-image marker.
    CHECK_THROWS_WITH(vkt::decode_image(Bytes{0xff, 0xd8, 0xff}, "three-bytes.jpg"),
                      StartsWith("three-bytes.jpg: cannot decode image: "));
}

TEST_CASE("decode_image refuses a truncated JPEG instead of greying its end", "[image_decode]") {
    const Bytes file = jpeg_of(16, 16, 3, gradient(16, 16, 3));
    const Bytes cut(file.begin(), file.end() - 40);  // inside the scan data
    CHECK_THROWS_WITH(vkt::decode_image(cut, "cut.jpg"),
                      "cut.jpg: cannot decode image: the file ends before its last pixels (cut "
                      "short?)");
}

TEST_CASE("decode_image refuses a JPEG larger than max_image_side from its header",
          "[image_decode]") {
    Bytes file = jpeg_of(16, 8, 3, gradient(16, 8, 3));
    // SOF0: FF C0, length (2), precision (1), height (2), width (2).
    const size_t sof = find(file, {0xff, 0xc0});
    file[sof + 5] = 0;
    file[sof + 6] = 100;  // 100 high
    file[sof + 7] = 0x4e;
    file[sof + 8] = 0x20;  // 20000 wide
    CHECK(vkt::read_image_size(file, "huge.jpg").width == 20000);
    CHECK_THROWS_WITH(vkt::decode_image(file, "huge.jpg"),
                      "huge.jpg: cannot decode image: it is 20000x100, larger than 16384x16384");
}

// A JPEG whose SOF0 header is made to claim width x height.
Bytes jpeg_claiming(Bytes file, uint32_t width, uint32_t height) {
    // SOF0: FF C0, length (2), precision (1), height (2), width (2).
    const size_t sof = find(file, {0xff, 0xc0});
    file[sof + 5] = uint8_t(height >> 8);
    file[sof + 6] = uint8_t(height);
    file[sof + 7] = uint8_t(width >> 8);
    file[sof + 8] = uint8_t(width);
    return file;
}

TEST_CASE("decode_image refuses a JPEG too small for the pixels its header claims",
          "[image_decode]") {
    // A 16 x 16 grey JPEG is a few hundred bytes; claiming 4096 x 4096 (inside
    // every budget: 235 MiB) it would need 262,144 blocks, at least 32 KiB.
    const Bytes small = jpeg_of(16, 16, 1, gradient(16, 16, 1));
    const Bytes claim = jpeg_claiming(small, 4096, 4096);
    CHECK_THROWS_WITH(vkt::decode_image(claim, "claim.jpg"),
                      "claim.jpg: cannot decode image: its header claims 4096x4096 pixels, "
                      "which its " +
                          std::to_string(claim.size()) +
                          " bytes cannot hold (a Huffman-coded JPEG spends at least a bit on "
                          "every 8x8 block of a scan)");
    // Colour, subsampled 2 x 2 by libjpeg's defaults: the chroma's blocks
    // (each covers 16 x 16 pixels) are the floor, 65,536 of them here.
    const Bytes colour = jpeg_claiming(jpeg_of(16, 16, 3, gradient(16, 16, 3)), 4096, 4096);
    CHECK_THROWS_WITH(vkt::decode_image(colour, "colour.jpg"),
                      Catch::Matchers::ContainsSubstring(
                          "which its " + std::to_string(colour.size()) + " bytes cannot hold"));
    // A real picture passes the floor by far: 512 x 512 of one grey is
    // 4,096 blocks of two short codes each.
    const Bytes flat = jpeg_of(512, 512, 1, Bytes(512 * 512, 128));
    CHECK(flat.size() * 8 >= 4096);
    CHECK(vkt::decode_image(flat, "flat.jpg").width == 512);
}

TEST_CASE("decode_image charges a JPEG's cost to the budget before decoding", "[image_decode]") {
    const Bytes file = jpeg_of(64, 64, 3, gradient(64, 64, 3));
    // 64 x 64: 16 KiB of pixels, 11/3 of that in all (59 KiB).
    vkt::MemoryBudget roomy(uint64_t(1) << 20);
    CHECK(vkt::decode_image(file, "a.jpg", roomy).width == 64);
    CHECK(roomy.used() == vkt::image_memory_cost(64, 64));
    // A progressive JPEG is decoded whole into coefficients first: 2 bytes
    // for each of its samples, 4096 of luma and 2 x 1024 of chroma here
    // (libjpeg's defaults subsample chroma 2 x 2).
    std::vector<jpeg_scan_info> scans = {{3, {0, 1, 2, 0}, 0, 0, 0, 0}};
    for (int component = 0; component < 3; ++component)
        scans.push_back({1, {component}, 1, 63, 0, 0});
    const Bytes progressive = jpeg_of(64, 64, 3, gradient(64, 64, 3), scans);
    vkt::MemoryBudget counted(uint64_t(1) << 20);
    CHECK(vkt::decode_image(progressive, "p.jpg", counted).width == 64);
    CHECK(counted.used() == vkt::image_memory_cost(64, 64) + (4096 + 2 * 1024) * 2);
    // Too little room: refused from the header, nothing charged.
    vkt::MemoryBudget tight(50 * 1024);
    CHECK_THROWS_WITH(vkt::decode_image(file, "a.jpg", tight),
                      "a.jpg: cannot decode image: it is 64x64: decoded, staged and mipmapped it "
                      "would take 59 KiB, past the 50 KiB limit (--max-memory)");
    CHECK(tight.used() == 0);
}

TEST_CASE("decode_image refuses a JPEG of too many progressive scans", "[image_decode]") {
    // The DC scan, then each AC coefficient of each component on its own:
    // 1 + 3 * 63 = 190 scans, a valid file, and each scan a pass over it all.
    std::vector<jpeg_scan_info> scans = {{3, {0, 1, 2, 0}, 0, 0, 0, 0}};
    for (int component = 0; component < 3; ++component)
        for (int k = 1; k < 64; ++k) scans.push_back({1, {component}, k, k, 0, 0});
    const Bytes file = jpeg_of(16, 8, 3, gradient(16, 8, 3), scans);
    CHECK_THROWS_WITH(vkt::decode_image(file, "scans.jpg"),
                      "scans.jpg: cannot decode image: more than 100 progressive scans");
}

TEST_CASE("read_image_size reads the header only", "[image_decode]") {
    const Bytes png = png_of(5, 3, PNG_FORMAT_RGBA, gradient(5, 3, 4).data());
    CHECK(vkt::read_image_size(png, "a.png").width == 5);
    CHECK(vkt::read_image_size(png, "a.png").height == 3);
    // The pixel data need not be there: libpng reads up to the first IDAT
    // chunk's type.
    const Bytes header_only(png.begin(), png.begin() + long(find(png, {'I', 'D', 'A', 'T'})) + 4);
    CHECK(vkt::read_image_size(header_only, "a.png").height == 3);
    const Bytes jpeg = jpeg_of(9, 17, 3, gradient(9, 17, 3));
    CHECK(vkt::read_image_size(jpeg, "b.jpg").width == 9);
    CHECK(vkt::read_image_size(jpeg, "b.jpg").height == 17);
    CHECK_THROWS_WITH(vkt::read_image_size(Bytes{'G', 'I', 'F', '8'}, "c.gif"),
                      "c.gif: cannot decode image: not a PNG or JPEG file");
}

TEST_CASE("write_png and decode_image agree on a file's bytes", "[image_decode]") {
    const auto path = std::filesystem::temp_directory_path() / "vkt_test_image_decode.png";
    vkt::RgbaImage image{7, 5, gradient(7, 5, 4)};
    vkt::write_png(path, image);
    CHECK(vkt::load_image_file(path).pixels == image.pixels);
    std::filesystem::remove(path);
    CHECK_THROWS_WITH(vkt::write_png("/no/such/dir/x.png", image),
                      ContainsSubstring("cannot write /no/such/dir/x.png"));
}
