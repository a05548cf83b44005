#pragma once
// Chapter 20's CPU side, apart from Vulkan: the structures shared with the
// shaders, the compute rasteriser's palette and the CPU reference that
// --verify compares the GPU with. The keys are chapter 18's
// (vkt/scene/ndim_controls.hpp).

#include "vkt/domains/ndim.hpp"
#include "vkt/resources/srgb.hpp"
#include "vkt/scene/ndim_controls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace ch20 {

namespace nd = vkt::ndim;

// The C++ side of shaders/20_ndim_compute/ndim.glsl.
struct Push {
    float to_clip[2];
    float eye;
    uint32_t orthographic, object_count, line_count;
    uint32_t size[2];
};
struct Projected {
    float x, y;
    uint32_t colour;  // alpha 0: at or behind the eye
    float depth;
};
struct ObjectInfo {
    uint32_t first_vertex, vertex_count, first_out;
    float inv_radius;
};
static_assert(sizeof(Projected) == 16 && sizeof(ObjectInfo) == 16 && sizeof(Push) == 32);

constexpr uint32_t group = 64;  // local_size_x of raster.comp

// [palette]
// The compute rasteriser's colours: word `level` (1..255; raster.comp stores
// the depth d = -1..1 as level 1 + (0.5 + 0.5 d) * 254, so t = (level - 1) / 254
// runs 0 far .. 1 near) is chapter 18's depth colour, sRGB-encoded as an
// _SRGB target stores it, in the target's byte order, with the level in the
// top byte (the target's alpha), so that atomicMax keeps the nearest line.
inline std::vector<uint32_t> palette(bool bgra) {
    const auto byte = [](float c) {  // linear to sRGB-encoded, 0..255
        return uint32_t(std::lround(std::clamp(vkt::linear_to_srgb(c), 0.0f, 1.0f) * 255.0f));
    };
    std::vector<uint32_t> words(256, 0u);  // level 0: no line
    for (uint32_t level = 1; level < 256; ++level) {
        const float t = float(level - 1) / 254.0f;  // 0 far .. 1 near
        const uint32_t r = byte(0.10f + 0.90f * t), g = byte(0.30f + 0.15f * t),
                       b = byte(1.00f - 0.90f * t);
        words[level] = (bgra ? b | g << 8 | r << 16 : r | g << 8 | b << 16) | level << 24;
    }
    return words;
}
// [/palette]

// --verify: the largest differences between the GPU's projected vertices
// (every object's, in scene order) and vkt::ndim's per-plane transform_point
// and project_to_2d, a different path from the matrix the shader uses.
struct Comparison {
    size_t vertices = 0, hidden = 0, mismatched = 0;  // mismatched: visible on one side only
    double position = 0.0, depth = 0.0;               // clip units; depth units (-1..1)
};

inline Comparison compare_with_cpu(const nd::Scene& scene, const nd::Controls& keys, float time,
                                   const Push& push, const Projected* gpu) {
    Comparison c;
    std::vector<float> world(size_t(scene.dim));
    for (const nd::SceneObject& object : scene.objects) {
        const nd::Transform t = keys.pose(object, time);
        const nd::Mesh& mesh = scene.meshes[size_t(object.mesh)];
        for (size_t i = 0; i < mesh.vertex_count(); ++i) {
            const Projected& g = gpu[c.vertices++];
            nd::transform_point(t, mesh.vertex(i), world);
            float xy[2];
            const bool visible = nd::project_to_2d(world, keys.projection, scene.eye, xy);
            const double depth = (world.back() - t.position.back()) / mesh.radius();
            c.depth = std::max(c.depth, std::abs(depth - g.depth));
            if (visible != (g.colour >> 24 != 0)) ++c.mismatched;
            if (!visible) {
                ++c.hidden;
                continue;
            }
            c.position = std::max({c.position, std::abs(double(xy[0] * push.to_clip[0]) - g.x),
                                   std::abs(double(xy[1] * push.to_clip[1]) - g.y)});
        }
    }
    return c;
}

}  // namespace ch20
