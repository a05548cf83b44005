#pragma once
// Screen tiles and their frusta, taught by chapter 17 (tiled deferred
// shading). The screen is cut into tile x tile pixel squares; each tile, with
// the range of depths its pixels hold, is a small frustum in view space, and a
// light (a sphere) is kept for the tile when it may touch that frustum.
//
// The GLSL twin is shaders/17_tiled_deferred/tiles.glsl: the SAME formulas.
// tests/unit/test_tiles.cpp checks them by hand and against brute force.
//
// Binning, chapter 17's second step: each light's rectangle of tiles, worked
// out once per light (light_tile_rect), and the tiles' bins filled by a count,
// a prefix sum and a fill (bin_by_tile, the CPU reference of the GPU's three
// passes). The GLSL twin is shaders/17_tiled_deferred/bins.glsl.

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

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

// A light's rectangle of tiles, [x0, x1] x [y0, y1]; empty when x0 > x1.
struct TileRect {
    uint32_t x0 = 1, y0 = 1, x1 = 0, y1 = 0;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

// The slopes u / t of the two lines through the eye that touch a circle of
// centre (u, t) and radius r, t in front of the eye (u: x or y; t: -z), from
// (u - s t)^2 = r^2 (1 + s^2). False when the circle reaches the eye's plane
// (t <= r): then lines of every slope meet it. t^2 - r^2 is written
// (t - r)(t + r), which stays accurate when t is close to r.
inline bool tangent_slopes(float u, float t, float r, float& lo, float& hi) {
    const float d = (t - r) * (t + r);
    if (!(t > r) || !(d > 0.0f)) return false;
    const float s = r * std::sqrt(u * u + d);
    lo = (u * t - s) / d;
    hi = (u * t + s) / d;
    return true;
}

// The tiles [first, last] of an axis `pixels` long that slopes [lo, hi] cover
// (NDC = scale * slope; scale < 0 flips), with a pixel of margin each side so
// that rounding never loses a tile. False when they miss the screen.
inline bool tile_span(float lo, float hi, float scale, uint32_t pixels, uint32_t tile,
                      uint32_t& first, uint32_t& last) {
    const float a = std::min(scale * lo, scale * hi), b = std::max(scale * lo, scale * hi);
    const float size = float(pixels);
    const float p0 = (a * 0.5f + 0.5f) * size - 1.0f, p1 = (b * 0.5f + 0.5f) * size + 1.0f;
    if (!(p1 >= 0.0f && p0 <= size)) return false;
    first = uint32_t(std::max(p0, 0.0f)) / tile;
    last = std::min(uint32_t(std::min(p1, size)) / tile, (pixels + tile - 1) / tile - 1);
    return true;
}

// The tiles a light (view-space centre, radius) may touch, whatever their
// depth ranges: every tile whose four side planes sphere_touches_tile would
// pass lies inside (tests/unit/test_tiles.cpp). A light wholly behind the eye
// touches none: every tile's near end lies in front of the eye.
inline TileRect light_tile_rect(const glm::mat4& proj, uint32_t width, uint32_t height,
                                uint32_t tile, glm::vec3 centre, float radius) {
    const float t = -centre.z;
    if (t + radius < 0.0f) return {};
    const TileGrid grid = tile_grid(width, height, tile);
    TileRect rect{0, 0, grid.x - 1, grid.y - 1};  // every tile, unless the slopes say less
    float lo = 0, hi = 0;
    if (tangent_slopes(centre.x, t, radius, lo, hi) &&
        !tile_span(lo, hi, proj[0][0], width, tile, rect.x0, rect.x1))
        return {};
    if (tangent_slopes(centre.y, t, radius, lo, hi) &&
        !tile_span(lo, hi, proj[1][1], height, tile, rect.y0, rect.y1))
        return {};
    return rect;
}

// The tiles' bins: tile t's candidates are lights[offsets[t] .. offsets[t] +
// counts[t]), every tile's one after another.
struct Bins {
    std::vector<uint32_t> counts, offsets, lights;
};

// The GPU's three passes, in order, on the CPU: count the lights of each
// tile's rectangle, an exclusive prefix sum of the counts gives each bin's
// start, and a fill writes each light into the bins of its rectangle. (The
// GPU fills in whatever order its atomics run; here, in light order.)
inline Bins bin_by_tile(const std::vector<TileRect>& rects, TileGrid grid) {
    Bins bins;
    bins.counts.assign(grid.count(), 0);
    auto each_tile = [&](const TileRect& r, auto&& visit) {
        for (uint32_t y = r.y0; y <= r.y1 && !r.empty(); ++y)
            for (uint32_t x = r.x0; x <= r.x1; ++x) visit(y * grid.x + x);
    };
    for (const TileRect& rect : rects) each_tile(rect, [&](uint32_t t) { ++bins.counts[t]; });
    bins.offsets.assign(grid.count(), 0);
    uint32_t total = 0;
    for (uint32_t t = 0; t < grid.count(); ++t) {
        bins.offsets[t] = total;
        total += bins.counts[t];
    }
    bins.lights.assign(total, 0);
    std::vector<uint32_t> filled(grid.count(), 0);
    for (uint32_t i = 0; i < rects.size(); ++i)
        each_tile(rects[i], [&](uint32_t t) { bins.lights[bins.offsets[t] + filled[t]++] = i; });
    return bins;
}

}  // namespace vkt
