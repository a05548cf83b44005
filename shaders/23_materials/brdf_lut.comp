#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's BRDF lookup table: the split sum's second factor, for n.v
// across and roughness down, as (A, B) with F0 A + B the share of the light
// the specular lobe reflects (split_sum_lut, pbr.glsl).
layout(local_size_x = 8, local_size_y = 8) in;
#include "pbr.glsl"
#include "cube.glsl"

layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D target;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(target);
    if (any(greaterThanEqual(p, size))) return;
    // Texel centres: the scene shader's linear sample at (n.v, roughness) finds them.
    vec2 at = (vec2(p) + 0.5) / vec2(size);
    imageStore(target, p, vec4(split_sum_lut(at.x, at.y, params.samples), 0.0, 1.0));
}
