#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 17, --shade lists: tiled_lighting.frag's work as a compute pass.
// After tiles.comp has written every tile's light list, one workgroup per tile
// and one invocation per pixel light the pixels from the list in memory, as
// the fragment shader does; only the launch differs (a dispatch, not a
// full-screen triangle through the rasteriser).
#include "tiles.glsl"

layout(local_size_x = 16, local_size_y = 16) in;  // TILE_SIZE x TILE_SIZE

layout(push_constant, std430) uniform TiledPush {
    int view;  // VIEW_LIT or VIEW_HEAT
} pass;

layout(set = 1, binding = 6, rgba32f) uniform writeonly image2D shaded;

uint tile;  // this invocation's tile, for TILE_LIGHT
#define TILE_LIGHT(i) tile_lights[tile * MAX_TILE_LIGHTS + (i)]
#include "tiled_shading.glsl"

void main() {
    uvec2 size = uvec2(textureSize(gbuffer_depth, 0));
    if (any(greaterThanEqual(gl_GlobalInvocationID.xy, size))) return;  // partial tiles
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    tile = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint found = tile_counts[tile];
    vec3 colour = shade_tile(pixel, size, min(found, MAX_TILE_LIGHTS), found, pass.view);
    imageStore(shaded, pixel, vec4(colour, 1.0));
}
