#include "vkt/scene/gbuffer.hpp"

#include "vkt/core/check.hpp"
#include "vkt/resources/srgb.hpp"

#include <algorithm>
#include <cmath>

namespace vkt {

namespace {
glm::vec2 sign_not_zero(glm::vec2 v) {
    return {v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f};
}
}  // namespace

glm::vec2 oct_encode(glm::vec3 n) {
    n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    const glm::vec2 xy(n.x, n.y);
    return n.z >= 0.0f ? xy : (1.0f - glm::abs(glm::vec2(n.y, n.x))) * sign_not_zero(xy);
}

glm::vec3 oct_decode(glm::vec2 e) {
    glm::vec3 n(e, 1.0f - std::abs(e.x) - std::abs(e.y));
    if (n.z < 0.0f) {
        const glm::vec2 folded =
            (1.0f - glm::abs(glm::vec2(n.y, n.x))) * sign_not_zero(glm::vec2(n.x, n.y));
        n.x = folded.x;
        n.y = folded.y;
    }
    return glm::normalize(n);
}

float srgb8_to_linear(uint8_t v) {
    return srgb_to_linear(float(v) / 255.0f);
}

float unorm8_to_float(uint8_t v) {
    return float(v) / 255.0f;
}

float snorm16_to_float(int16_t v) {
    return std::max(float(v) / 32767.0f, -1.0f);
}

glm::vec3 position_from_depth(const glm::mat4& inverse_view_proj, uint32_t x, uint32_t y,
                              uint32_t width, uint32_t height, float depth) {
    const glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f,
                        (float(y) + 0.5f) / float(height) * 2.0f - 1.0f);
    const glm::vec4 world = inverse_view_proj * glm::vec4(ndc, depth, 1.0f);
    return glm::vec3(world) / world.w;
}

std::vector<glm::vec3> shade_gbuffer(const GBufferTexels& g, const glm::mat4& inverse_view_proj,
                                     glm::vec3 camera_position, glm::vec3 ambient,
                                     std::span<const PointLight> lights, glm::vec3 background,
                                     const std::function<void(uint32_t)>& rows_done) {
    const size_t count = size_t{g.width} * g.height;
    if (g.base_colour.size() != count * 4 || g.normal.size() != count * 2 ||
        g.material.size() != count * 4 || g.depth.size() != count ||
        (!g.albedo_as_read.empty() && g.albedo_as_read.size() != count))
        throw Error("shade_gbuffer: the G-buffer's arrays do not match its size");
    std::vector<glm::vec3> out(count);
    for (uint32_t y = 0; y < g.height; ++y) {
        for (uint32_t x = 0; x < g.width; ++x) {
            const size_t i = size_t{y} * g.width + x;
            if (g.depth[i] == 1.0f) {
                out[i] = background;
                continue;
            }
            const glm::vec3 albedo = !g.albedo_as_read.empty()
                                         ? g.albedo_as_read[i]
                                         : glm::vec3(srgb8_to_linear(g.base_colour[i * 4 + 0]),
                                                     srgb8_to_linear(g.base_colour[i * 4 + 1]),
                                                     srgb8_to_linear(g.base_colour[i * 4 + 2]));
            const glm::vec3 normal = oct_decode(
                {snorm16_to_float(g.normal[i * 2 + 0]), snorm16_to_float(g.normal[i * 2 + 1])});
            const LightingParams params{
                .ambient = ambient,
                .falloff = Falloff::windowed,
                .specular = unorm8_to_float(g.material[i * 4 + 0]),
                .shininess = float(g.material[i * 4 + 1]),  // stored as shininess / 255
            };
            const glm::vec3 position =
                position_from_depth(inverse_view_proj, x, y, g.width, g.height, g.depth[i]);
            out[i] = shade(position, normal, albedo, camera_position, lights, params);
        }
        if (rows_done) rows_done(y + 1);
    }
    return out;
}

}  // namespace vkt
