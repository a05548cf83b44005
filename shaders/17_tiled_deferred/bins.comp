#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 17, --cull binned: the light pass, one invocation per light, run
// twice a frame (a specialization constant chooses). COUNT (FILL false): the
// light's view-space sphere and its rectangle of tiles, stored for the later
// passes, and one count in the bin of every tile of the rectangle. FILL,
// after bin_scan.comp has turned the counts into each bin's start: the
// light's index, written into those bins.
#define TILE_WRITER
#include "tiles.glsl"
#include "bins.glsl"

layout(local_size_x = 256) in;
layout(constant_id = 0) const bool FILL = false;

// [light-pass]
void main() {
    uint light = gl_GlobalInvocationID.x;
    if (light >= frame.light_count) return;
    uvec2 size = uvec2(textureSize(gbuffer_depth, 0));
    uint tiles_x = (size.x + TILE_SIZE - 1) / TILE_SIZE;
    uvec4 rect;
    if (!FILL) {  // once per light: its sphere and its rectangle
        vec4 sphere = view_sphere(lights[light]);
        light_spheres[light] = sphere;
        rect = light_tile_rect(sphere.xyz, sphere.w, size);
        light_rects[light] = uvec2(rect.x | rect.z << 16, rect.y | rect.w << 16);
    } else {
        uvec2 bits = light_rects[light];
        rect = uvec4(bits & 0xffffu, bits >> 16);  // x0, y0, x1, y1
    }
    for (uint y = rect.y; y <= rect.w; ++y)
        for (uint x = rect.x; x <= rect.z; ++x) {
            uint tile = y * tiles_x + x;
            if (!FILL) {
                atomicAdd(bin_counts[tile], 1);  // count
            } else {  // the scan set the counts back to 0: they count again
                uint slot = bin_offsets[tile] + atomicAdd(bin_counts[tile], 1);
                if (slot < bin_lights.length()) bin_lights[slot] = light;  // beyond: dropped, and reported
            }
        }
}
// [/light-pass]
