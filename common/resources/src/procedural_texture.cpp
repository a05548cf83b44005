#include "vkt/resources/procedural_texture.hpp"

#include "vkt/core/check.hpp"

#include <array>
#include <string>

namespace vkt {

namespace {

struct Rgb {
    uint8_t r, g, b;
};

// Twelve colours that tell apart at a glance (sRGB bytes).
constexpr std::array<Rgb, 12> kPalette{{
    {220, 50, 40},    // red
    {240, 140, 30},   // orange
    {235, 205, 40},   // yellow
    {120, 190, 40},   // lime
    {30, 140, 60},    // green
    {30, 180, 170},   // teal
    {40, 150, 230},   // sky
    {40, 70, 190},    // blue
    {120, 60, 190},   // violet
    {200, 60, 170},   // magenta
    {240, 130, 150},  // pink
    {140, 90, 50},    // brown
}};
constexpr Rgb kLightGround{235, 230, 215};
constexpr Rgb kDarkGround{35, 35, 45};

// floor(sqrt(v)), exactly, in integers.
uint32_t integer_sqrt(uint32_t v) {
    uint32_t root = 0;
    while ((root + 1) * (root + 1) <= v) ++root;
    return root;
}

// Whether texel (x, y) shows the pattern's colour (true) or the ground.
bool in_pattern(uint32_t pattern, uint32_t x, uint32_t y, uint32_t size, uint32_t period) {
    const uint32_t half = period / 2;
    switch (pattern) {
        case 0:
            return ((x / half) + (y / half)) % 2 == 0;  // checker
        case 1:
            return (y / half) % 2 == 0;  // horizontal stripes
        case 2:
            return ((x + y) / half) % 2 == 0;  // diagonal stripes
        case 3: {                              // a dot in every cell
            const int dx = int(x % period) - int(half), dy = int(y % period) - int(half);
            return uint32_t(dx * dx + dy * dy) * 9 < period * period;  // radius period / 3
        }
        case 4: {  // rings around the centre
            const int dx = int(x) - int(size / 2), dy = int(y) - int(size / 2);
            return (integer_sqrt(uint32_t(dx * dx + dy * dy)) / half) % 2 == 0;
        }
        default: {  // bricks: rows half a period high, every other row shifted
            const uint32_t row = y / half;
            const uint32_t shifted = x + (row % 2) * half;
            return y % half != 0 && shifted % period != 0;  // mortar lines are ground
        }
    }
}

}  // namespace

RgbaImage procedural_texture(uint32_t index, uint32_t size) {
    if (size < 16 || size > 1024 || (size & (size - 1)) != 0)
        throw Error("procedural_texture: size must be a power of two from 16 to 1024, not " +
                    std::to_string(size));
    index %= procedural_texture_variety;
    const uint32_t pattern = index % 6;
    const Rgb ink = kPalette[index % 12];
    const Rgb ground = (index / 12) % 2 == 0 ? kLightGround : kDarkGround;
    const uint32_t period = size / (2 + 2 * ((index / 24) % 4));  // size/2 .. size/8, even

    RgbaImage image{size, size, std::vector<uint8_t>(size_t(size) * size * 4)};
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const Rgb c = in_pattern(pattern, x, y, size, period) ? ink : ground;
            uint8_t* texel = &image.pixels[(size_t(y) * size + x) * 4];
            texel[0] = c.r;
            texel[1] = c.g;
            texel[2] = c.b;
            texel[3] = 255;
        }
    return image;
}

}  // namespace vkt
