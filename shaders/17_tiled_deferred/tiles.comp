#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 17: one workgroup per 16 x 16 tile, one invocation per pixel.
// It finds the tile's depth range, culls every light (--cull tiled) or the
// candidates in the tile's bin (--cull binned) against the tile's frustum,
// and then either writes the tile's light list (--shade fragment: the
// fragment pass lights) or lights its own pixel from the list in shared
// memory and stores it (--shade compute: culling and shading in one dispatch).
#define TILE_WRITER
#include "tiles.glsl"
#include "bins.glsl"

layout(local_size_x = 16, local_size_y = 16) in;  // TILE_SIZE x TILE_SIZE
// Chosen when the pipeline is made: false for the cull pass, true for cull + shade;
// false to test every light, true to test the tile's bin.
layout(constant_id = 0) const bool SHADE = false;
layout(constant_id = 1) const bool BINNED = false;

layout(push_constant, std430) uniform TiledPush {
    int view;
} pass;

layout(set = 1, binding = 6, rgba32f) uniform writeonly image2D shaded;  // --shade compute

// [shared]
shared uint depth_min_bits, depth_max_bits;     // the tile's depth range, as bits
shared uint found;                              // lights that touch the tile
shared uint list[MAX_TILE_LIGHTS];              // the first MAX_TILE_LIGHTS of them
// [/shared]

#define TILE_LIGHT(i) list[i]
#include "tiled_shading.glsl"

// [keep]
// Appends a light that touches the tile to the shared list.
void keep(uint light) {
    uint slot = atomicAdd(found, 1);
    if (slot < MAX_TILE_LIGHTS) list[slot] = light;  // beyond: counted, not stored
}
// [/keep]

// [cull-binned]
// --cull binned: the test is the same, but only the tile's candidates take it,
// the lights that the light pass put in this tile's bin; their view-space
// spheres too were worked out once, there.
void cull_binned(TileFrustum f, uint tile) {
    uint first = bin_offsets[tile], capacity = bin_lights.length();
    uint candidates = first < capacity ? min(bin_counts[tile], capacity - first) : 0;
    for (uint k = gl_LocalInvocationIndex; k < candidates; k += TILE_SIZE * TILE_SIZE) {
        uint light = bin_lights[first + k];
        vec4 sphere = light_spheres[light];
        if (sphere_touches_tile(f, sphere.xyz, sphere.w)) keep(light);
    }
    if (gl_LocalInvocationIndex == 0) atomicMax(stats.most_candidates, candidates);
}
// [/cull-binned]

void main() {
    uvec2 size = uvec2(textureSize(gbuffer_depth, 0));
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    bool inside = all(lessThan(gl_GlobalInvocationID.xy, size));  // the last tiles are partial
    float depth = inside ? texelFetch(gbuffer_depth, pixel, 0).r : 1.0;

    // [depth-range]
    // The tile's nearest and farthest drawn pixel: a min/max reduction in
    // shared memory. Depths in [0, 1] order like their bit patterns as uints.
    if (gl_LocalInvocationIndex == 0) {
        depth_min_bits = floatBitsToUint(1.0);
        depth_max_bits = 0;
        found = 0;
    }
    memoryBarrierShared();
    barrier();
    if (depth < 1.0) {  // the background (depth 1) needs no light
        atomicMin(depth_min_bits, floatBitsToUint(depth));
        atomicMax(depth_max_bits, floatBitsToUint(depth));
    }
    memoryBarrierShared();
    barrier();
    // [/depth-range]

    // [cull]
    // All 256 invocations share the lights: invocation k tests lights k,
    // k + 256, k + 512, ... and appends those that touch to the shared list.
    bool drawn = depth_min_bits != floatBitsToUint(1.0);
    uint tile = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (drawn) {
        TileFrustum f = tile_frustum(gl_WorkGroupID.xy, size,
                                     view_depth(uintBitsToFloat(depth_min_bits)),
                                     view_depth(uintBitsToFloat(depth_max_bits)));
        if (BINNED) {
            cull_binned(f, tile);
        } else {
            for (uint i = gl_LocalInvocationIndex; i < frame.light_count;
                 i += TILE_SIZE * TILE_SIZE) {
                vec4 sphere = view_sphere(lights[i]);  // the centre in view space
                if (sphere_touches_tile(f, sphere.xyz, sphere.w)) keep(i);
            }
        }
    }
    memoryBarrierShared();
    barrier();
    uint count = min(found, MAX_TILE_LIGHTS);
    // [/cull]

    if (gl_LocalInvocationIndex == 0 && drawn) {
        atomicAdd(stats.lit_tiles, 1);
        atomicAdd(stats.total_lights, found);
        atomicMax(stats.most_lights, found);
        if (found > MAX_TILE_LIGHTS) atomicAdd(stats.overflowed_tiles, 1);
    }

    // [write-list]
    if (!SHADE) {  // --shade fragment: store the list for the lighting pass
        if (gl_LocalInvocationIndex == 0) tile_counts[tile] = found;
        for (uint i = gl_LocalInvocationIndex; i < count; i += TILE_SIZE * TILE_SIZE)
            tile_lights[tile * MAX_TILE_LIGHTS + i] = list[i];
        return;
    }
    // [/write-list]
    // [shade]
    // --shade compute: every invocation lights its own pixel from the shared list.
    if (inside)
        imageStore(shaded, pixel, vec4(shade_tile(pixel, size, count, found, pass.view), 1.0));
    // [/shade]
}
