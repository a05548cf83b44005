// PNG and JPEG decoding, for every picture the project reads: chapter 09's
// textures, chapter 10's glTF images (whatever bytes a model brings), the
// tests' screenshots and golden images. PNG goes to libpng and JPEG to
// libjpeg-turbo: the reference decoders, maintained, and fuzzed without end
// by OSS-Fuzz. (It was stb_image, until tests/fuzz/fuzz_image.cpp crashed
// its JPEG decoder: tests/fuzz/regressions/image/.)
//
// Both libraries report an error by calling a function that must not return.
// Ours longjmp back to the setjmp in the function that called the library.
// A longjmp skips C++ destructors, so those four functions (png_header,
// png_pixels, jpeg_header, jpeg_pixels) own nothing: what they fill lives in
// the caller's reader, whose destructor frees the library's state whether
// the jump happened or not. Between a library call and its setjmp there are
// only the library's C frames and our callbacks, which own nothing either.

#include "vkt/resources/image_io.hpp"

#include "image_messages.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/core/memory_budget.hpp"

#include <png.h>
// jpeglib.h uses size_t and FILE without including their headers.
#include <jpeglib.h>
#include <cstddef>
#include <cstdio>

#include <algorithm>
#include <climits>
#include <csetjmp>
#include <cstring>
#include <utility>

#ifndef JCS_ALPHA_EXTENSIONS
#error "vkt needs libjpeg-turbo's jpeglib.h (JCS_EXT_RGBA), not another libjpeg's"
#endif

namespace vkt {

namespace {

// --- PNG: libpng --------------------------------------------------------------

struct PngReader {
    std::span<const uint8_t> bytes;
    size_t offset = 0;  // how far libpng has read
    png_structp png = nullptr;
    png_infop info = nullptr;
    char error[256] = "";    // why it stopped: libpng's words, or ours
    char warning[256] = "";  // libpng's last warning: the reason for some errors
    uint32_t width = 0, height = 0;
    int bit_depth = 0, channels = 0;  // as stored in the file
    std::vector<uint8_t> pixels;
    std::vector<png_bytep> rows;

    explicit PngReader(std::span<const uint8_t> in) : bytes(in) {}
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;
    ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
};

// libpng's error handler: keep its message, jump back (returning would make
// libpng abort the program).
[[noreturn]] void png_failed(png_structp png, png_const_charp message) {
    auto* reader = static_cast<PngReader*>(png_get_error_ptr(png));
    std::snprintf(reader->error, sizeof reader->error, "%s", message);
    png_longjmp(png, 1);
}

// A warning is about an ancillary chunk (a colour profile, a text) that
// libpng found damaged and skipped; the picture is whole. libpng would
// print it on stderr: say nothing, but keep it, since libpng also warns with
// the reason for an error it then gives in general words ("Invalid IHDR data").
void png_warned(png_structp png, png_const_charp message) {
    auto* reader = static_cast<PngReader*>(png_get_error_ptr(png));
    std::snprintf(reader->warning, sizeof reader->warning, "%s", message);
}

// libpng reads through this: from memory, never past the end.
void png_read_bytes(png_structp png, png_bytep out, size_t length) {
    auto* reader = static_cast<PngReader*>(png_get_io_ptr(png));
    if (length > reader->bytes.size() - reader->offset) png_error(png, "the file ends early");
    std::memcpy(out, reader->bytes.data() + reader->offset, length);
    reader->offset += length;
}

// The chunks before the pixel data, the header (IHDR) first: the size,
// nothing decoded.
bool png_header(PngReader& r) {
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r, png_failed, png_warned);
    if (r.png) r.info = png_create_info_struct(r.png);
    if (!r.png || !r.info) {
        std::snprintf(r.error, sizeof r.error, "libpng cannot start (out of memory?)");
        return false;
    }
    if (setjmp(png_jmpbuf(r.png))) return false;
    png_set_read_fn(r.png, &r, png_read_bytes);
    png_read_info(r.png, r.info);
    r.width = png_get_image_width(r.png, r.info);
    r.height = png_get_image_height(r.png, r.info);
    r.bit_depth = png_get_bit_depth(r.png, r.info);
    r.channels = png_get_channels(r.png, r.info);
    return true;
}

// Deflate shrinks data at most about 1032 times (a run of 258 bytes in
// 2 bits, at best), so a PNG's file is at least its filtered rows / 1032:
// one filter byte and the row's packed samples each. A header that claims
// more pixels than that is a lie, refused before anything is allocated.
constexpr uint64_t deflate_max_ratio = 1032;
bool png_plausible(const PngReader& r, size_t file_size) {
    const uint64_t row = 1 + (uint64_t(r.width) * uint64_t(r.bit_depth) * r.channels + 7) / 8;
    return uint64_t(r.height) * row <= deflate_max_ratio * file_size;
}

// A palette PNG's rows, read as one index a byte at the start of each RGBA
// row, become RGBA in place (from the right, so no index is overwritten
// before it is read). libpng's own expansion draws an index past the palette
// black without a word (libpng 1.6.39 reports nothing), so the indices are
// looked up here, each checked.
bool png_palette_to_rgba(PngReader& r) {
    png_colorp palette = nullptr;
    int colours = 0;
    png_get_PLTE(r.png, r.info, &palette, &colours);
    png_bytep alpha = nullptr;
    int alphas = 0;
    if (png_get_valid(r.png, r.info, PNG_INFO_tRNS))
        png_get_tRNS(r.png, r.info, &alpha, &alphas, nullptr);
    for (size_t y = 0; y < r.height; ++y) {
        uint8_t* row = r.rows[y];
        for (size_t x = r.width; x-- > 0;) {
            const uint8_t index = row[x];
            if (index >= colours) {
                std::snprintf(r.error, sizeof r.error,
                              "pixel (%zu, %zu) is palette index %d, past the end of its palette "
                              "of %d colours",
                              x, y, index, colours);
                return false;
            }
            row[4 * x + 3] = index < alphas ? alpha[index] : 0xFF;
            row[4 * x + 2] = palette[index].blue;
            row[4 * x + 1] = palette[index].green;
            row[4 * x] = palette[index].red;
        }
    }
    return true;
}

// The pixels, every kind of PNG converted to 8-bit RGBA on the way.
bool png_pixels(PngReader& r) {
    if (setjmp(png_jmpbuf(r.png))) return false;
    const bool palette = png_get_color_type(r.png, r.info) == PNG_COLOR_TYPE_PALETTE;
    if (palette) {
        png_set_packing(r.png);  // one index a byte, looked up by png_palette_to_rgba
    } else {
        png_set_expand(r.png);    // grey below 8 bits to 8, tRNS to alpha
        png_set_strip_16(r.png);  // 16-bit channels: their high byte
        png_set_gray_to_rgb(r.png);
        png_set_add_alpha(r.png, 0xff, PNG_FILLER_AFTER);  // opaque where there is no alpha
    }
    png_set_interlace_handling(r.png);  // Adam7: libpng puts the passes together
    png_read_update_info(r.png, r.info);
    // libpng writes each row blind: check that a row is what we allocate.
    const int channels = palette ? 1 : 4;
    if (png_get_bit_depth(r.png, r.info) != 8 || png_get_channels(r.png, r.info) != channels ||
        png_get_rowbytes(r.png, r.info) != size_t(r.width) * size_t(channels))
        png_error(r.png, "not 8-bit RGBA (or palette indices) after conversion");
    r.pixels.resize(size_t(r.width) * r.height * 4);
    r.rows.resize(r.height);
    for (size_t y = 0; y < r.height; ++y) r.rows[y] = r.pixels.data() + y * r.width * 4;
    png_read_image(r.png, r.rows.data());
    png_read_end(r.png, nullptr);  // the rest of the file, checksums included
    return !palette || png_palette_to_rgba(r);
}

// --- JPEG: libjpeg-turbo ------------------------------------------------------

struct JpegErrors {
    jpeg_error_mgr manager;  // first: libjpeg's pointer to it is one to the whole
    std::jmp_buf jump;
    char text[JMSG_LENGTH_MAX];
};

struct JpegReader {
    std::span<const uint8_t> bytes;
    JpegErrors errors{};
    jpeg_decompress_struct info{};
    jpeg_progress_mgr progress{};
    std::vector<uint8_t> pixels;

    explicit JpegReader(std::span<const uint8_t> in) : bytes(in) {}
    JpegReader(const JpegReader&) = delete;
    JpegReader& operator=(const JpegReader&) = delete;
    // Also right for a struct jpeg_create_decompress never finished: it frees
    // only what was allocated.
    ~JpegReader() { jpeg_destroy_decompress(&info); }
};

// libjpeg's error handler: its message, then jump back. Its default one
// prints and calls exit(): a corrupt texture would end the program.
[[noreturn]] void jpeg_failed(j_common_ptr info) {
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    (*info->err->format_message)(info, errors->text);
    std::longjmp(errors->jump, 1);
}

// Level -1 is a warning: the data is corrupt, and libjpeg would carry on
// with made-up pixels (grey to the end of a file cut short). Refuse it, as
// `djpeg -strict` does. Levels 0 and up are trace messages.
void jpeg_message(j_common_ptr info, int level) {
    if (level < 0) jpeg_failed(info);
}
void jpeg_silent(j_common_ptr) {}

// Each scan of a progressive JPEG is a pass over the whole picture, and a
// few bytes make a scan: thousands of them make a small file take minutes
// (the TurboJPEG API has a scan limit for this). Encoders write about ten.
constexpr int max_jpeg_scans = 100;
void jpeg_count_scans(j_common_ptr info) {
    if (!info->is_decompressor) return;
    if (reinterpret_cast<j_decompress_ptr>(info)->input_scan_number <= max_jpeg_scans) return;
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    std::snprintf(errors->text, sizeof errors->text, "more than %d progressive scans",
                  max_jpeg_scans);
    std::longjmp(errors->jump, 1);
}

// The markers up to the first scan: the size, nothing decoded.
bool jpeg_header(JpegReader& r) {
    r.info.err = jpeg_std_error(&r.errors.manager);
    r.errors.manager.error_exit = jpeg_failed;
    r.errors.manager.emit_message = jpeg_message;
    r.errors.manager.output_message = jpeg_silent;
    if (setjmp(r.errors.jump)) return false;
    jpeg_create_decompress(&r.info);
    r.progress.progress_monitor = jpeg_count_scans;
    r.info.progress = &r.progress;  // after create, which clears the struct
    jpeg_mem_src(&r.info, r.bytes.data(), static_cast<unsigned long>(r.bytes.size()));
    if (jpeg_read_header(&r.info, TRUE) != JPEG_HEADER_OK) {
        std::snprintf(r.errors.text, sizeof r.errors.text, "no picture in the file");
        return false;
    }
    return true;
}

// The blocks of 8 x 8 samples component `c` has, as libjpeg-turbo counts
// them (a component sampled at half the rate covers twice the pixels).
uint64_t jpeg_component_blocks(const jpeg_decompress_struct& info, int c) {
    const jpeg_component_info& component = info.comp_info[c];
    const uint64_t block_width = 8 * uint64_t(info.max_h_samp_factor);  // in pixels
    const uint64_t block_height = 8 * uint64_t(info.max_v_samp_factor);
    const uint64_t across =
        (uint64_t(info.image_width) * uint64_t(component.h_samp_factor) + block_width - 1) /
        block_width;
    const uint64_t down =
        (uint64_t(info.image_height) * uint64_t(component.v_samp_factor) + block_height - 1) /
        block_height;
    return across * down;
}

// A Huffman-coded JPEG spends at least one bit on every block of a scan
// (the shortest Huffman code, for "DC unchanged" or a refinement bit), and
// a file whose scan ends early is refused (jpeg_message): so its bytes are
// at least the blocks of its smallest component / 8. A header that claims
// more is a lie, refused before anything is allocated. Arithmetic coding,
// which libjpeg-turbo also decodes, can spend far less than a bit on a
// block of one flat colour, so it has no such floor: only the budget
// holds it.
bool jpeg_plausible(const jpeg_decompress_struct& info, size_t file_size) {
    if (info.arith_code) return true;
    // The fewest blocks a scan can cover: those of the component sampled most
    // coarsely (a JPEG's first scan may hold that component alone).
    uint64_t fewest = UINT64_MAX;
    for (int c = 0; c < info.num_components; ++c)
        fewest = std::min(fewest, jpeg_component_blocks(info, c));
    return fewest <= uint64_t(file_size) * 8;
}

// What libjpeg-turbo itself allocates beyond our pixels: a progressive (or
// multi-scan) JPEG is decoded whole before its first row comes out, into
// 64 coefficients of 2 bytes for every block of every component.
uint64_t jpeg_coefficient_bytes(const jpeg_decompress_struct& info) {
    if (!info.progressive_mode && info.comps_in_scan == info.num_components) return 0;
    uint64_t blocks = 0;
    for (int c = 0; c < info.num_components; ++c) blocks += jpeg_component_blocks(info, c);
    return blocks * 64 * sizeof(JCOEF);
}

// The pixels, as RGBA straight from libjpeg-turbo (alpha 255); colour and
// grey JPEGs both. CMYK ones are refused by libjpeg ("Unsupported color
// conversion request", said in words by jpeg_reason).
bool jpeg_pixels(JpegReader& r) {
    if (setjmp(r.errors.jump)) return false;
    r.info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&r.info);
    // libjpeg writes each row blind: check that a row is what we allocate.
    if (r.info.output_components != 4 || r.info.output_width != r.info.image_width ||
        r.info.output_height != r.info.image_height) {
        std::snprintf(r.errors.text, sizeof r.errors.text, "not RGBA at full size");
        return false;
    }
    const size_t stride = size_t(r.info.output_width) * 4;
    r.pixels.resize(stride * r.info.output_height);
    while (r.info.output_scanline < r.info.output_height) {
        JSAMPROW row = r.pixels.data() + stride * r.info.output_scanline;
        jpeg_read_scanlines(&r.info, &row, 1);  // from memory: never suspends
    }
    jpeg_finish_decompress(&r.info);  // the rest of the file, up to its end marker
    return true;
}

// Why libjpeg-turbo stopped, in words (image_messages.cpp).
std::string jpeg_reason(const JpegReader& r) {
    return image_detail::jpeg_reason(r.errors.manager.msg_code, r.errors.text,
                                     r.info.jpeg_color_space, r.info.num_components);
}

// --- Both ---------------------------------------------------------------------

[[noreturn]] void cannot_decode(const std::string& what, const std::string& reason) {
    throw Error(what + ": cannot decode image: " + reason);
}

// PNG and JPEG only, told by their first bytes: glTF allows no other, and
// neither do this tutorial's pages. (stb_image, before, also read TGA, which
// has no signature, so any bytes at all could pass for a picture of garbage:
// found by tests/fuzz/fuzz_image.cpp, 20 bytes "decoded" to 2848x2816.)
enum class Kind { png, jpeg };
Kind kind_of(std::span<const uint8_t> bytes, const std::string& what) {
    // jpeg_mem_src's length is an unsigned long: 32 bits on Windows. Nothing
    // here comes near (vkt::read_file stops at 1 GiB).
    if (bytes.size() > size_t(INT_MAX)) cannot_decode(what, "larger than 2 GiB");
    if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG\r\n\x1a\n", 8) == 0)
        return Kind::png;
    if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff)
        return Kind::jpeg;
    cannot_decode(what, "not a PNG or JPEG file");
}

}  // namespace

ImageSize read_image_size(std::span<const uint8_t> bytes, const std::string& what) {
    if (kind_of(bytes, what) == Kind::png) {
        PngReader reader(bytes);
        if (!png_header(reader))
            cannot_decode(what, image_detail::png_reason(reader.error, reader.warning));
        return {reader.width, reader.height};
    }
    JpegReader reader(bytes);
    if (!jpeg_header(reader)) cannot_decode(what, jpeg_reason(reader));
    return {reader.info.image_width, reader.info.image_height};
}

RgbaImage decode_image(std::span<const uint8_t> bytes, const std::string& what) {
    MemoryBudget budget;
    return decode_image(bytes, what, budget);
}

RgbaImage decode_image(std::span<const uint8_t> bytes, const std::string& what,
                       MemoryBudget& budget) {
    // A few hundred bytes may claim a picture of gigabytes, and the decoder
    // would allocate it all before finding the data missing (found by
    // tests/fuzz/fuzz_image.cpp). Refuse, from the header alone, what no
    // texture of this tutorial could hold, and what the budget has no room
    // for; `decoder` is what the library allocates besides our pixels.
    auto check_size = [&](uint32_t width, uint32_t height, uint64_t decoder) {
        const std::string size = std::to_string(width) + "x" + std::to_string(height);
        if (width > max_image_side || height > max_image_side)
            cannot_decode(what, "it is " + size + ", larger than " +
                                    std::to_string(max_image_side) + "x" +
                                    std::to_string(max_image_side));
        const uint64_t cost = image_memory_cost(width, height) + decoder;
        if (cost > budget.limit() - budget.used())
            cannot_decode(
                what, "it is " + size + ": decoded, staged and mipmapped it would take " +
                          byte_count_text(cost) + ", past the " + byte_count_text(budget.limit()) +
                          " limit (--max-memory)" +
                          (budget.used() == 0 ? std::string()
                                              : " with the " + byte_count_text(budget.used()) +
                                                    " the file needs besides"));
        budget.charge(cost, what);
    };
    if (kind_of(bytes, what) == Kind::png) {
        PngReader reader(bytes);
        if (!png_header(reader))
            cannot_decode(what, image_detail::png_reason(reader.error, reader.warning));
        check_size(reader.width, reader.height, 0);
        if (!png_plausible(reader, bytes.size()))
            cannot_decode(what, "its header claims " + std::to_string(reader.width) + "x" +
                                    std::to_string(reader.height) + " pixels, which its " +
                                    std::to_string(bytes.size()) +
                                    " bytes cannot hold (PNG's compression shrinks at most " +
                                    std::to_string(deflate_max_ratio) + " times)");
        if (!png_pixels(reader))
            cannot_decode(what, image_detail::png_reason(reader.error, reader.warning));
        return {reader.width, reader.height, std::move(reader.pixels)};
    }
    JpegReader reader(bytes);
    if (!jpeg_header(reader)) cannot_decode(what, jpeg_reason(reader));
    check_size(reader.info.image_width, reader.info.image_height,
               jpeg_coefficient_bytes(reader.info));
    if (!jpeg_plausible(reader.info, bytes.size()))
        cannot_decode(what, "its header claims " + std::to_string(reader.info.image_width) + "x" +
                                std::to_string(reader.info.image_height) + " pixels, which its " +
                                std::to_string(bytes.size()) +
                                " bytes cannot hold (a Huffman-coded JPEG spends at least a bit "
                                "on every 8x8 block of a scan)");
    if (!jpeg_pixels(reader)) cannot_decode(what, jpeg_reason(reader));
    return {reader.info.output_width, reader.info.output_height, std::move(reader.pixels)};
}

uint64_t image_memory_cost(uint32_t width, uint32_t height) {
    const uint64_t pixels = uint64_t(width) * height * 4;
    return pixels + 2 * (pixels * 4 / 3);
}

RgbaImage load_image_file(const std::filesystem::path& path) {
    MemoryBudget budget;
    return load_image_file(path, budget);
}

RgbaImage load_image_file(const std::filesystem::path& path, MemoryBudget& budget) {
    // Its first bytes say whether it is a PNG or a JPEG at all, before a
    // file of up to 1 GiB is read whole.
    const std::vector<char> start = read_file_start(path, 8);  // throws "cannot open FILE"
    kind_of(std::span(reinterpret_cast<const uint8_t*>(start.data()), start.size()),
            shown_path(path));
    budget.charge(readable_file_size(path), shown_path(path));  // the file's bytes, read
    std::vector<char> file = read_file(path);
    return decode_image(std::span(reinterpret_cast<const uint8_t*>(file.data()), file.size()),
                        shown_path(path), budget);
}

}  // namespace vkt
