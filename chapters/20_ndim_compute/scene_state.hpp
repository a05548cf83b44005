#pragma once
// Chapter 20's CPU side, apart from Vulkan: the structures shared with the
// shaders, the compute rasteriser's palette, the keys' state (chapter 18's
// controls) and the CPU reference that --verify compares the GPU with.

#include "vkt/domains/ndim.hpp"
#include "vkt/frame/input.hpp"

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

// [palette]
// The compute rasteriser's colours: word `level` (1..255, the depth
// t = (level - 1) / 127 - 1) is chapter 18's depth colour, sRGB-encoded as an
// _SRGB target stores it, in the target's byte order, with the level in the
// top byte (the target's alpha), so that atomicMax keeps the nearest line.
inline std::vector<uint32_t> palette(bool bgra) {
    const auto byte = [](float c) {  // linear to sRGB-encoded, 0..255
        c = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
        return uint32_t(std::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f);
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

// [controls]
// The keys of chapter 18: 1..9, 0 turn the planes of the current page,
// [ and ] change the page, F1..F12 move along the axes, Shift reverses,
// Space pauses, O switches the projection, R resets. Headless, input is
// always empty and the picture depends on the frame index alone.
struct Keys {
    int n = 4, page = 0;
    bool paused = false, orthographic = false;
    std::vector<float> angles, offset;  // added to every object's pose

    Keys(int dim, bool ortho)
        : n(dim),
          orthographic(ortho),
          angles(size_t(nd::plane_count(dim)), 0.0f),
          offset(size_t(dim), 0.0f) {}

    void steer(const vkt::Input& input, float dt) {
        constexpr int key_0 = 48, key_1 = 49, key_o = 79, key_r = 82, key_left_bracket = 91,
                      key_right_bracket = 93, key_f1 = 290;  // GLFW key codes
        const float sign = input.shift() ? -1.0f : 1.0f;
        const int planes = nd::plane_count(n), pages = (planes + 9) / 10;
        if (input.went_down(key_right_bracket) || input.went_down(key_left_bracket))
            page = (page + (input.went_down(key_right_bracket) ? 1 : pages - 1)) % pages;
        for (int key = 0; key < 10; ++key) {
            const int plane = page * 10 + key, code = key == 9 ? key_0 : key_1 + key;
            if (plane < planes && input.down(code)) angles[size_t(plane)] += sign * dt;
        }
        for (int axis = 0; axis < std::min(n, 12); ++axis)
            if (input.down(key_f1 + axis)) offset[size_t(axis)] += sign * 1.5f * dt;
        if (input.went_down(vkt::key::space)) paused = !paused;
        if (input.went_down(key_o)) orthographic = !orthographic;
        if (input.went_down(key_r)) {
            std::fill(angles.begin(), angles.end(), 0.0f);
            std::fill(offset.begin(), offset.end(), 0.0f);
        }
    }

    // An object's pose at `time`: its start plus spin * time, plus the keys.
    nd::Transform pose(const nd::SceneObject& object, float time) const {
        nd::Transform t = object.at(time);
        for (size_t p = 0; p < t.angles.size(); ++p) t.angles[p] += angles[p];
        for (int k = 0; k < n; ++k) t.position[size_t(k)] += offset[size_t(k)];
        return t;
    }
};
// [/controls]

// --verify: the largest differences between the GPU's projected vertices
// (every object's, in scene order) and vkt::ndim's per-plane transform_point
// and project_to_2d, a different path from the matrix the shader uses.
struct Comparison {
    size_t vertices = 0, hidden = 0, mismatched = 0;  // mismatched: visible on one side only
    double position = 0.0, depth = 0.0;               // clip units; depth units (-1..1)
};

inline Comparison compare_with_cpu(const nd::Scene& scene, const Keys& keys, float time,
                                   const Push& push, const Projected* gpu) {
    Comparison c;
    std::vector<float> world(size_t(scene.dim));
    const auto kind =
        keys.orthographic ? nd::Projection::orthographic : nd::Projection::perspective;
    for (const nd::SceneObject& object : scene.objects) {
        const nd::Transform t = keys.pose(object, time);
        const nd::Mesh& mesh = scene.meshes[size_t(object.mesh)];
        for (size_t i = 0; i < mesh.vertex_count(); ++i) {
            const Projected& g = gpu[c.vertices++];
            nd::transform_point(t, mesh.vertex(i), world);
            float xy[2];
            const bool visible = nd::project_to_2d(world, kind, scene.eye, xy);
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
