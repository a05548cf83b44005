// libFuzzer target: vkt::decode_image (chapter 09's texture path, and the
// images of chapter 10's glTF files) on any bytes. The seed corpus has PNG
// and JPEG files. The contract: a decoded RGBA8 image whose pixel count
// matches its size, or vkt::Error; anything else is a finding.
//
// A PNG or JPEG whose header claims more than 2^20 pixels is skipped: a few
// bytes can claim 16384 x 16384, and the decoder then fills a gigabyte (a
// JPEG cut short is an error only at its end), which under ASan takes
// seconds per input while running the same code as a small picture.
// decode_image's own limit on such files (max_image_side) is checked by
// tests/unit/test_texture.cpp. The size comes from vkt::read_image_size, the
// decoders' own header reading; bytes it refuses go on to decode_image,
// which must refuse them too.
#include "vkt/core/check.hpp"
#include "vkt/resources/image_io.hpp"

#include <cstdint>
#include <cstdlib>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::span<const uint8_t> bytes(data, size);
    try {
        const vkt::ImageSize claimed = vkt::read_image_size(bytes, "fuzz input");
        if (uint64_t(claimed.width) * claimed.height > (uint64_t(1) << 20)) return 0;
    } catch (const vkt::Error&) {
    }
    try {
        const vkt::RgbaImage image = vkt::decode_image(bytes, "fuzz input");
        if (image.width == 0 || image.height == 0) std::abort();
        if (image.pixels.size() != size_t(image.width) * image.height * 4) std::abort();
    } catch (const vkt::Error&) {
    }
    return 0;
}
