// libFuzzer target: vkt::decode_image (chapter 09's texture path, and the
// images of chapter 10's glTF files) on any bytes. The seed corpus has PNG
// and JPEG files. The contract: a decoded RGBA8 image whose pixel count
// matches its size, or vkt::Error; anything else is a finding.
//
// A PNG or JPEG whose header claims more than 2^20 pixels is skipped: a few bytes
// can claim 16384 x 16384, and stb_image then decodes a gigabyte of garbage,
// which under ASan takes minutes (a hang, to libFuzzer) while running the
// same code as a small picture. decode_image's own limit on such files
// (max_image_side) is checked by tests/unit/test_texture.cpp.
#include "vkt/core/check.hpp"
#include "vkt/resources/texture.hpp"

#include <stb_image.h>

#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // Only a PNG or JPEG reaches stb's decoder (decode_image refuses the rest
    // from their first bytes, which the fuzzer should see it do).
    const bool png = size >= 8 && std::memcmp(data, "\x89PNG\r\n\x1a\n", 8) == 0;
    const bool jpeg = size >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff;
    int width = 0, height = 0, channels = 0;
    if ((png || jpeg) && size <= size_t(INT_MAX) &&
        stbi_info_from_memory(data, int(size), &width, &height, &channels) &&
        int64_t(width) * height > (int64_t(1) << 20))
        return 0;
    try {
        const vkt::RgbaImage image = vkt::decode_image(std::span(data, size), "fuzz input");
        if (image.width == 0 || image.height == 0) std::abort();
        if (image.pixels.size() != size_t(image.width) * image.height * 4) std::abort();
    } catch (const vkt::Error&) {
    }
    return 0;
}
