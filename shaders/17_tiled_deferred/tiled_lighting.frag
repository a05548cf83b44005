#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 17, --shade fragment: after tiles.comp has written every tile's
// light list, one full-screen triangle lights each pixel from its tile's list.
#include "tiles.glsl"

layout(push_constant, std430) uniform TiledPush {
    int view;  // VIEW_LIT or VIEW_HEAT
} pass;

layout(location = 0) out vec4 target;

// [fragment-lighting]
uint tile;  // this pixel's tile, for TILE_LIGHT
#define TILE_LIGHT(i) tile_lights[tile * MAX_TILE_LIGHTS + (i)]
#include "tiled_shading.glsl"

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uvec2 size = uvec2(textureSize(gbuffer_depth, 0));
    uint tiles_x = (size.x + TILE_SIZE - 1) / TILE_SIZE;
    tile = (uint(pixel.y) / TILE_SIZE) * tiles_x + uint(pixel.x) / TILE_SIZE;
    uint found = tile_counts[tile];
    target = vec4(shade_tile(pixel, size, min(found, MAX_TILE_LIGHTS), found, pass.view), 1.0);
}
// [/fragment-lighting]
