#pragma once
// Screen tiles and their frusta, taught by chapter 17 (tiled deferred
// shading). The screen is cut into tile x tile pixel squares; each tile, with
// the range of depths its pixels hold, is a small frustum in view space, and a
// light (a sphere) is kept for the tile when it may touch that frustum.
//
// The GLSL twin is shaders/17_tiled_deferred/tiles.glsl: the SAME formulas.
// tests/unit/test_tiles.cpp checks them by hand and against brute force.

#include <glm/glm.hpp>

#include <algorithm>
#include <cstdint>

namespace vkt {

// How many tiles cover a width x height screen: the last column and row are
// partial unless the size is a multiple of the tile.
struct TileGrid {
    uint32_t x = 0, y = 0;
    uint32_t count() const { return x * y; }
};
constexpr TileGrid tile_grid(uint32_t width, uint32_t height, uint32_t tile) {
    return {(width + tile - 1) / tile, (height + tile - 1) / tile};
}

// The distance in front of the camera (view-space -z) of a depth-buffer value,
// for a perspective projection with depth 0..1 (vkt::vulkan_perspective):
// clip z = P[2][2] z + P[3][2] and clip w = -z give depth = -P[2][2] + P[3][2] / t.
inline float view_depth(const glm::mat4& proj, float depth) {
    return proj[3][2] / (depth + proj[2][2]);
}

// A tile's frustum in view space: four planes through the eye (dot(n, p) >= 0
// inside, n unit length) and the depth range [near, far] of its pixels.
struct TileFrustum {
    glm::vec3 planes[4];
    float near = 0, far = 0;
};

// The frustum of tile (tx, ty) of a width x height screen. The projection must
// be a symmetric perspective one (no shear): a view-space point p lands on
// NDC x = P[0][0] p.x / -p.z, y = P[1][1] p.y / -p.z. The tile's pixels span
// [x0, x1] x [y0, y1], clipped to the screen, so the side planes bound the
// slopes p.x / -p.z and p.y / -p.z.
inline TileFrustum tile_frustum(const glm::mat4& proj, uint32_t width, uint32_t height, uint32_t tx,
                                uint32_t ty, uint32_t tile, float near, float far) {
    auto slope = [](uint32_t pixel, uint32_t size, float scale) {
        return (float(pixel) / float(size) * 2.0f - 1.0f) / scale;
    };
    const float ax = slope(tx * tile, width, proj[0][0]);
    const float bx = slope(std::min((tx + 1) * tile, width), width, proj[0][0]);
    float ay = slope(ty * tile, height, proj[1][1]);
    float by = slope(std::min((ty + 1) * tile, height), height, proj[1][1]);
    if (ay > by) std::swap(ay, by);  // Vulkan's P[1][1] < 0: y flips
    // x / -z >= ax  <=>  x + ax z >= 0;   x / -z <= bx  <=>  -x - bx z >= 0.
    TileFrustum f;
    f.planes[0] = glm::normalize(glm::vec3(1.0f, 0.0f, ax));
    f.planes[1] = glm::normalize(glm::vec3(-1.0f, 0.0f, -bx));
    f.planes[2] = glm::normalize(glm::vec3(0.0f, 1.0f, ay));
    f.planes[3] = glm::normalize(glm::vec3(0.0f, -1.0f, -by));
    f.near = near;
    f.far = far;
    return f;
}

// May a sphere (view-space centre, radius) touch the frustum? It is culled
// only when it lies wholly outside one plane or beyond the depth range, so a
// sphere that touches the frustum is never culled (conservative); one near a
// corner may be kept without touching it, which costs time, never correctness.
inline bool sphere_touches_tile(const TileFrustum& f, glm::vec3 centre, float radius) {
    const float t = -centre.z;  // distance in front of the eye
    if (t + radius < f.near || t - radius > f.far) return false;
    for (const glm::vec3& n : f.planes)
        if (glm::dot(n, centre) < -radius) return false;
    return true;
}

}  // namespace vkt
