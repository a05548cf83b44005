#pragma once
// Small procedural textures, made in C++ at start-up: chapter 15 needs dozens
// of distinct textures to show bindless texturing, and drawing them here keeps
// the repository free of image files. Integer arithmetic only, so every
// machine makes the same bytes.

#include "vkt/resources/image_io.hpp"

#include <cstdint>

namespace vkt {

// How many distinct textures procedural_texture makes: index i and i + 96
// give the same picture.
inline constexpr uint32_t procedural_texture_variety = 96;

// Texture `index` at size x size texels (size a power of two, 16 to 1024;
// throws Error otherwise): one of six patterns (checker, horizontal stripes,
// diagonal stripes, dots, rings, bricks) by index % 6, drawn in one of twelve
// colours (index % 12) on a light or a dark ground ((index / 12) % 2), at one
// of four scales ((index / 24) % 4: a period of size/2, size/4, size/6 or
// size/8 texels). Opaque, sRGB-encoded bytes: upload it as R8G8B8A8_SRGB.
RgbaImage procedural_texture(uint32_t index, uint32_t size);

}  // namespace vkt
