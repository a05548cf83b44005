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
// Whether to look at a pixel before the atomicMax (tuning.hpp chooses: on a
// GPU always; on a CPU device only where lines overlap densely, as the look
// there costs about what the writes it saves do).
layout(constant_id = 1) const bool LOOK_FIRST = true;
// The transform pass's output, through its set (TransformPass::projected_binding).
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
// Set 1, ComputeRaster's: ends_binding, pixels_binding, palette_binding.
layout(std430, set = 1, binding = 0) readonly buffer Lines { uint ends[]; };
layout(std430, set = 1, binding = 1) buffer Pixels { uint pixels[]; };
// The colour is chapter 18's depth colour, a function of the depth alone, so
// each of the 255 depth levels has one word, built once on the CPU: the
// colour sRGB-encoded in the target's byte order, the level in the top byte.
layout(std430, set = 1, binding = 2) readonly buffer Palette { uint palette[256]; };
#include "walk.glsl"

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
    Walk w;
    if (!start_walk(projected[ends[2u * line]], projected[ends[2u * line + 1u]], w)) return;

    // [pixels]
    // Every LANES-th step of the walk (walk.glsl), the pixels outside the
    // image left out.
    for (int i = w.first + int(lane); i <= w.last; i += int(LANES)) {
        float t;
        const int j = walk_minor(w, i, t);
        if (j < 0 || j >= int(w.x_major ? push.size.y : push.size.x)) continue;
        const uint word = walk_word(w, t);
        const uint at = w.x_major ? uint(j) * push.size.x + uint(i) : uint(i) * push.size.x + uint(j);
        // LOOK_FIRST: look before the read-modify-write. Where a nearer line
        // has the pixel already, which is most pixels where thousands of
        // lines overlap, a plain (relaxed) atomic load is all it costs. Words
        // only grow, so a load that misses a newer word only costs an
        // atomicMax. Either way the pixel ends with the largest word.
        if (!LOOK_FIRST || atomicLoad(pixels[at], gl_ScopeDevice, gl_StorageSemanticsBuffer,
                                      gl_SemanticsRelaxed) < word)
            atomicMax(pixels[at], word);
    }
    // [/pixels]
}
