#version 450
// Chapter 20: the compute rasteriser. One or more invocations per line walk
// its pixels and keep, in each, the nearest line's colour. Each pixel is one
// 32-bit word laid out as the colour target's pixel: three sRGB-encoded
// colour bytes in the target's order, and in the top byte (the target's
// alpha, which the screen does not show) the depth. atomicMax keeps the
// largest word, the nearest line, whatever order the invocations run in; a
// copy then moves the words to the colour target unchanged.
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_memory_scope_semantics : require
#include "ndim.glsl"

layout(local_size_x = 64) in;
// How many invocations share a line (1 to 32, a power of two): chosen when
// the pipeline is built, from the number of lines.
layout(constant_id = 0) const uint LANES = 1;
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
layout(std430, set = 0, binding = 4) readonly buffer Lines { uint ends[]; };
layout(std430, set = 0, binding = 5) buffer Pixels { uint pixels[]; };
// The colour is chapter 18's depth colour, a function of the depth alone, so
// each of the 255 depth levels has one word, built once on the CPU: the
// colour sRGB-encoded in the target's byte order, the level in the top byte.
layout(std430, set = 0, binding = 6) readonly buffer Palette { uint palette[256]; };

// [lanes]
// LANES invocations share a line, each taking every LANES-th pixel: with few
// lines (one n-cube) a long line is walked by many lanes at once, and the
// GPU has enough invocations to fill its compute units. The dispatch is
// two-dimensional (x has a limit of 65,535 workgroups on some devices), so
// the flat index is rebuilt from both.
void main() {
    const uint index = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) *
                           gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    const uint line = index / LANES, lane = index % LANES;
    if (line >= push.line_count) return;
    // [/lanes]
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
    const float per_pixel = 1.0 / d[major];  // t's step from one pixel to the next
    for (int i = first + int(lane); i <= last; i += int(LANES)) {
        const float t = (float(i) + 0.5 - p0[major]) * per_pixel;  // 0 at a, 1 at b
        const int j = int(floor(p0[minor] + t * d[minor]));
        if (j < 0 || j >= int(push.size[minor])) continue;
        // The depth t = -1..1 as level 1..255 (0 is the background).
        const float depth = clamp(0.5 + 0.5 * mix(a.depth, b.depth, t), 0.0, 1.0);
        const uint word = palette[1u + uint(depth * 254.0 + 0.5)];
        const uint at = major == 0 ? uint(j) * push.size.x + uint(i) : uint(i) * push.size.x + uint(j);
        // Look before the read-modify-write: where a nearer line has the
        // pixel already, which is most pixels where thousands of lines
        // overlap, a plain (relaxed) atomic load is all it costs. Words only
        // grow, so a load that misses a newer word only costs an atomicMax.
        if (atomicLoad(pixels[at], gl_ScopeDevice, gl_StorageSemanticsBuffer,
                       gl_SemanticsRelaxed) < word)
            atomicMax(pixels[at], word);
    }
    // [/walk]
}
