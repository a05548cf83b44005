// The memory an image may make a chapter spend (vkt/resources/image_io.hpp):
// from its header alone, before anything is decoded, an image is refused if
// it would cost more than its budget (default_max_memory, or --max-memory), or if the file is too
// small to hold what its header claims (issue 25: a 69-byte PNG claiming 16384 x 16384
// allocated 1.15 GB and took 4 s before it failed).

#include "peak_resident.hpp"
#include "vkt/core/check.hpp"
#include "vkt/resources/image_io.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using Catch::Matchers::ContainsSubstring;

namespace {

void put_u32_big(std::vector<uint8_t>& out, uint32_t value) {
    for (int i = 3; i >= 0; --i) out.push_back(uint8_t(value >> (8 * i)));
}

// A PNG whose IHDR claims width x height 8-bit RGBA, followed by a 12-byte
// IDAT: the start of a zlib stream and nothing like the rows it promises.
std::vector<uint8_t> png_claiming(uint32_t width, uint32_t height) {
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto chunk = [&](const char* type, const std::vector<uint8_t>& data) {
        put_u32_big(png, uint32_t(data.size()));
        const size_t start = png.size();
        png.insert(png.end(), type, type + 4);
        png.insert(png.end(), data.begin(), data.end());
        put_u32_big(png, uint32_t(crc32(0, png.data() + start, uInt(png.size() - start))));
    };
    std::vector<uint8_t> ihdr;
    put_u32_big(ihdr, width);
    put_u32_big(ihdr, height);
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});
    chunk("IHDR", ihdr);
    chunk("IDAT", {0x78, 0x9c, 0x63, 0x60, 0x18, 0x05, 0, 0, 0, 0, 0, 0});
    chunk("IEND", {});
    return png;
}

std::string error_of(const std::vector<uint8_t>& bytes) {
    try {
        vkt::decode_image(bytes, "claim.png");
    } catch (const vkt::Error& e) {
        return e.what();
    }
    return "(decoded)";
}

}  // namespace

TEST_CASE("image budget: pixels, a staging copy and two mip chains are counted", "[texture]") {
    // 8192 x 8192 x 4 = 256 MiB; + 2 x 4/3 of it: 939 MiB, inside 1 GiB.
    CHECK(vkt::image_memory_cost(8192, 8192) == 268435456ull + 2 * 357913941ull);
    CHECK(vkt::image_memory_cost(8192, 8192) <= vkt::default_max_memory);
    CHECK(vkt::image_memory_cost(16384, 16384) > vkt::default_max_memory);
    CHECK(vkt::image_memory_cost(1, 1) == 4 + 2 * 5);
}

TEST_CASE(
    "image budget: a PNG claiming 16384 x 16384 with 69 bytes is refused before any large "
    "allocation",
    "[texture]") {
    const std::vector<uint8_t> claim = png_claiming(16384, 16384);
    REQUIRE(claim.size() == 69);
    REQUIRE(vkt_test::reset_peak_resident());
    const double before = vkt_test::peak_resident_mib();
    CHECK_THAT(error_of(claim),
               ContainsSubstring("claim.png: cannot decode image: it is 16384x16384: decoded, "
                                 "staged and mipmapped it would take 3755 MiB, past the 1 GiB "
                                 "limit (--max-memory)"));
    const double after = vkt_test::peak_resident_mib();
    std::printf("peak resident memory: %.1f MiB before the refusal, %.1f MiB after\n", before,
                after);
    // Before the budget, libpng and our pixel vector took 1.15 GB here.
    CHECK(after < before + 16.0);
}

TEST_CASE("image budget: a PNG too small for the pixels its header claims is refused",
          "[texture]") {
    // 4096 x 4096 is inside the budget (235 MiB of 1 GiB), but 69 bytes inflate to at
    // most 71 KB, not the 64 MiB of its rows.
    CHECK_THAT(error_of(png_claiming(4096, 4096)),
               ContainsSubstring("claim.png: cannot decode image: its header claims 4096x4096 "
                                 "pixels, which its 69 bytes cannot hold"));
    // 8 x 8 needs 264 bytes of rows: 69 may hold them; the decoder says what is wrong.
    CHECK_THAT(error_of(png_claiming(8, 8)),
               !ContainsSubstring("cannot hold") && ContainsSubstring("claim.png: cannot decode"));
}
