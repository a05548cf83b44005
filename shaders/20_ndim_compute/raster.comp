#version 450
// Chapter 20: the compute rasteriser. One invocation per line walks its
// pixels and keeps, in each, the nearest line's colour. Each pixel is one
// 32-bit word laid out as the colour target's pixel: three sRGB-encoded
// colour bytes in the target's order, and in the top byte, the target's
// alpha, which the screen does not show, the depth. atomicMax keeps the largest word, the nearest line,
// whatever order the invocations run in; a copy then moves the words to the
// colour target unchanged.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

layout(local_size_x = 64) in;
// 1: the target is B8G8R8A8 (blue in the lowest byte), 0: R8G8B8A8.
layout(constant_id = 0) const int BGRA = 1;
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
layout(std430, set = 0, binding = 4) readonly buffer Lines { uint ends[]; };
layout(r32ui, set = 0, binding = 5) uniform uimage2D raster;

// What an _SRGB target does on a write: linear to sRGB-encoded.
vec3 srgb_encode(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
    const uint line = gl_GlobalInvocationID.x;
    if (line >= push.line_count) return;
    const Projected a = projected[ends[2u * line]], b = projected[ends[2u * line + 1u]];
    if ((a.colour >> 24) == 0u || (b.colour >> 24) == 0u) return;  // an end behind the eye

    // [walk]
    // Clip space to pixels, then one step per pixel along the major axis:
    // at each pixel centre c on that axis, the line's other coordinate picks
    // the pixel. The last pixel is left to the next line (half-open, like the
    // hardware's lines), and the walk is clamped to the image.
    const vec2 size = vec2(push.size);
    const vec2 p0 = (a.xy * 0.5 + 0.5) * size, p1 = (b.xy * 0.5 + 0.5) * size, d = p1 - p0;
    const int major = abs(d.x) >= abs(d.y) ? 0 : 1, minor = 1 - major;
    if (d[major] == 0.0) return;  // a line of length 0 covers no pixel centre
    const bool forward = d[major] > 0.0;
    const float start = forward ? p0[major] : p1[major], end = forward ? p1[major] : p0[major];
    const int first = max(int(ceil(start - 0.5)), 0);
    const int last = min(int(ceil(end - 0.5)), int(push.size[major])) - 1;
    const vec4 ca = unpackUnorm4x8(a.colour), cb = unpackUnorm4x8(b.colour);
    for (int i = first; i <= last; ++i) {
        const float t = (float(i) + 0.5 - p0[major]) / d[major];  // 0 at a, 1 at b
        const int j = int(floor(p0[minor] + t * d[minor]));
        if (j < 0 || j >= int(push.size[minor])) continue;
        // Depth 1..255 (0 is the background) in the alpha byte; the colour
        // interpolated in linear values, then encoded, as the hardware does.
        const float depth = clamp(0.5 + 0.5 * mix(a.depth, b.depth, t), 0.0, 1.0);
        const vec3 c = srgb_encode(mix(ca.rgb, cb.rgb, t));
        const uint packed = packUnorm4x8(vec4(BGRA == 1 ? c.bgr : c, 0.0)) & 0xffffffu;
        imageAtomicMax(raster, major == 0 ? ivec2(i, j) : ivec2(j, i),
                       packed | (1u + uint(depth * 254.0 + 0.5)) << 24);
    }
    // [/walk]
}
