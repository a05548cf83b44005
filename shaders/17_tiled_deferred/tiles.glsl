// Chapter 17's shared declarations: chapter 16's blocks (frame uniforms,
// lights, shade_all), the G-buffer, the tiles' light lists, and the tile
// frustum test. The C++ twin of the frustum maths is common/include/vkt/tiles.hpp.
#include "deferred/blocks.glsl"
#include "deferred/normal_encoding.glsl"

// [limits]
const uint TILE_SIZE = 16;           // a tile is 16 x 16 pixels: one workgroup of 256
const uint MAX_TILE_LIGHTS = 2048;   // the longest light list a tile stores
// [/limits]

// The writers (tiles.comp) declare TILE_WRITER; the fragment pass only reads.
#ifdef TILE_WRITER
#define TILE_ACCESS
#else
#define TILE_ACCESS readonly
#endif

// Set 1: what is as large as the screen (rewritten when it is resized).
layout(set = 1, binding = 0) uniform sampler2D gbuffer_base_colour;
layout(set = 1, binding = 1) uniform sampler2D gbuffer_normal;
layout(set = 1, binding = 2) uniform sampler2D gbuffer_params;
layout(set = 1, binding = 3) uniform sampler2D gbuffer_depth;
// [tile-buffers]
// For each tile, how many lights touch it (the true number, which may exceed
// MAX_TILE_LIGHTS), and its list: MAX_TILE_LIGHTS slots per tile.
layout(set = 1, binding = 4, std430) TILE_ACCESS buffer TileCounts {
    uint tile_counts[];
};
layout(set = 1, binding = 5, std430) TILE_ACCESS buffer TileLights {
    uint tile_lights[];  // tile t's list: tile_lights[t * MAX_TILE_LIGHTS ...]
};
// [/tile-buffers]

const int VIEW_LIT = 0, VIEW_HEAT = 5;  // 1..4 are chapter 16's G-buffer views

// [tile-frustum]
// A tile's frustum in view space: four planes through the eye (dot(n, p) >= 0
// inside) and the distances [near, far] in front of the eye of its pixels.
struct TileFrustum {
    vec3 planes[4];
    float near, far;
};

// The distance in front of the eye of a depth-buffer value: depth =
// -P[2][2] + P[3][2] / t for a perspective projection with depth 0..1.
float view_depth(float depth) {
    return frame.proj[3][2] / (depth + frame.proj[2][2]);
}

// Tile `tile` of a `size` screen spans pixels [x0, x1] x [y0, y1]. A view-space
// point p lands on NDC x = P[0][0] p.x / -p.z: the tile bounds the slope
// p.x / -p.z between two numbers, and each bound is a plane through the eye.
TileFrustum tile_frustum(uvec2 tile, uvec2 size, float near, float far) {
    vec2 lo = vec2(tile * TILE_SIZE), hi = vec2(min((tile + 1) * TILE_SIZE, size));
    vec2 scale = vec2(frame.proj[0][0], frame.proj[1][1]);
    vec2 a = (lo / vec2(size) * 2.0 - 1.0) / scale, b = (hi / vec2(size) * 2.0 - 1.0) / scale;
    if (a.y > b.y) { float t = a.y; a.y = b.y; b.y = t; }  // P[1][1] < 0 flips y
    TileFrustum f;
    f.planes[0] = normalize(vec3(1.0, 0.0, a.x));    // x / -z >= a.x
    f.planes[1] = normalize(vec3(-1.0, 0.0, -b.x));  // x / -z <= b.x
    f.planes[2] = normalize(vec3(0.0, 1.0, a.y));
    f.planes[3] = normalize(vec3(0.0, -1.0, -b.y));
    f.near = near;
    f.far = far;
    return f;
}

// Culled only when wholly outside one plane or beyond the depth range: a
// sphere that touches the frustum is always kept (conservative).
bool sphere_touches_tile(TileFrustum f, vec3 centre, float radius) {
    float t = -centre.z;
    if (t + radius < f.near || t - radius > f.far) return false;
    for (int i = 0; i < 4; ++i) {
        precise float side = dot(f.planes[i], centre);  // see view_sphere
        if (side < -radius) return false;
    }
    return true;
}
// [/tile-frustum]

// A light's sphere in view space: centre and radius. `precise` forbids the
// compiler to fuse a multiply and an add here and not there: every pass that
// computes it gets the same bits, so that culling every light (--cull tiled)
// and culling the binned candidates (--cull binned) keep the same lights.
vec4 view_sphere(PointLight light) {
    precise vec3 centre = (frame.view * vec4(light.position, 1.0)).xyz;
    return vec4(centre, light.radius);
}

#ifdef TILE_WRITER
// Per frame (set 0, binding 2): what the CPU reports after the frame; TileStats
// in tile_pass.hpp.
layout(set = 0, binding = 2, std430) buffer TileStats {
    uint overflowed_tiles;  // tiles with more than MAX_TILE_LIGHTS lights
    uint most_lights;       // the most lights any tile had
    uint total_lights;      // summed over the tiles
    uint lit_tiles;         // tiles with something drawn
    uint binned_entries;    // --cull binned: the candidates in all bins (the scan's total)
    uint binned_budget;     // --cull binned: the room for them (beyond it, dropped)
    uint most_candidates;   // --cull binned: the most candidates a lit tile tested
} stats;
#endif
