#pragma once
// The G-buffer of chapter 16 on the CPU: decoding what the GPU stored (an
// _SRGB base colour, an octahedral R16G16_SNORM normal, an R8G8B8A8_UNORM
// material, a D32_SFLOAT depth), rebuilding each pixel's world position from
// depth, and lighting it with vkt::shade (vkt/scene/lighting.hpp). The deferred
// chapters (16, 17) read their G-buffers back and compare their lighting
// passes with shade_gbuffer; the unit tests check the pieces.
//
// The GLSL twins are shaders/common/deferred/normal_encoding.glsl and
// lighting.frag: the SAME formulas.

#include "vkt/scene/lighting.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace vkt {

// Octahedral encoding of a unit vector into [-1, 1]^2, and back (normalised).
glm::vec2 oct_encode(glm::vec3 n);
glm::vec3 oct_decode(glm::vec2 e);

// The value a shader reads from a stored texel: sRGB 8-bit to linear (the
// exact sRGB curve), UNORM8 to [0, 1], SNORM16 to [-1, 1] (-32768 reads as -1).
float srgb8_to_linear(uint8_t v);
float unorm8_to_float(uint8_t v);
float snorm16_to_float(int16_t v);

// A G-buffer as read back: width * height texels each, rows top to bottom.
struct GBufferTexels {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> base_colour;  // R8G8B8A8_SRGB: 4 bytes a texel
    std::vector<int16_t> normal;       // R16G16_SNORM: 2 values a texel, octahedral
    std::vector<uint8_t> material;     // R8G8B8A8_UNORM: specular, shininess / 255, -, -
    std::vector<float> depth;          // D32_SFLOAT: 1 a texel
    // Optional: the base colour as the GPU decoded it (read back through a
    // float target). sRGB decoding is allowed some error: lavapipe's is off by
    // up to about 0.2%. When given, shade_gbuffer lights these values instead
    // of decoding base_colour with the exact curve, so that only the lighting
    // formulas are compared.
    std::vector<glm::vec3> albedo_as_read;
};

// The world position of pixel (x, y)'s centre at `depth`: clip space
// ((x + 0.5) / w * 2 - 1, (y + 0.5) / h * 2 - 1, depth, 1) through
// inverse_view_proj, divided by w (Vulkan's clip space: y down, depth 0..1).
glm::vec3 position_from_depth(const glm::mat4& inverse_view_proj, uint32_t x, uint32_t y,
                              uint32_t width, uint32_t height, float depth);

// Lights every texel with vkt::shade (windowed falloff, the texel's own
// specular strength and shininess, `ambient` times the albedo), in linear RGB;
// texels with depth 1 (nothing drawn) get `background`. Returns width * height
// colours, rows top to bottom. `rows_done`, where given, is called after each
// row with the number of rows lit so far (for progress output: a reference
// with tens of thousands of lights runs for minutes).
std::vector<glm::vec3> shade_gbuffer(const GBufferTexels& gbuffer,
                                     const glm::mat4& inverse_view_proj, glm::vec3 camera_position,
                                     glm::vec3 ambient, std::span<const PointLight> lights,
                                     glm::vec3 background,
                                     const std::function<void(uint32_t)>& rows_done = {});

}  // namespace vkt
