#version 460

// One level of chapter 28's depth pyramid: each texel the min (the farthest,
// depth being reversed) of the 2 x 2 texels of the level below, the depth
// buffer itself below level 0. Sizes halve rounding up, and reads past the
// edge clamp to it, so every texel below is covered by one above.

layout(local_size_x = 8, local_size_y = 8) in;
// [reduce]
// 1: the sampler does the min (VK_SAMPLER_REDUCTION_MODE_MIN, linear
// filtering: one sample between four texels returns their min); 0: four
// texel fetches and min() in the shader, for devices without it.
layout(constant_id = 0) const bool SAMPLER_MIN = true;
layout(set = 0, binding = 0) uniform sampler2D below;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D level;

layout(push_constant) uniform Sizes {
    ivec2 below_size, level_size;
} sizes;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, sizes.level_size))) return;
    float farthest;
    if (SAMPLER_MIN) {
        // The corner shared by texels 2p and 2p + 1: linear filtering's
        // footprint is exactly those four (clamped at the edge).
        farthest = textureLod(below, vec2(2 * p + 1) / vec2(sizes.below_size), 0.0).r;
    } else {
        ivec2 last = sizes.below_size - 1, a = 2 * p;
        farthest = min(min(texelFetch(below, min(a, last), 0).r,
                           texelFetch(below, min(a + ivec2(1, 0), last), 0).r),
                       min(texelFetch(below, min(a + ivec2(0, 1), last), 0).r,
                           texelFetch(below, min(a + ivec2(1, 1), last), 0).r));
    }
    imageStore(level, p, vec4(farthest));
}
// [/reduce]
