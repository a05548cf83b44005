#version 450
// Chapter 20, --raster binned, pass 1 of 3: the pixels each chunk of 64 lines
// may touch, as a box, and each object's box, the union of its chunks'
// boxes. One invocation per chunk: row y of the dispatch is the object, x its
// chunks, 64 to a workgroup.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"
#include "bins.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
layout(std430, set = 0, binding = 4) readonly buffer Lines { uint ends[]; };
layout(std430, set = 0, binding = 7) readonly buffer Objects { LineRange objects[]; };
layout(std430, set = 0, binding = 8) writeonly buffer ChunkBoxes { uvec2 chunk_boxes[]; };
// Per object, (0xffff - lo.x, 0xffff - lo.y, hi.x, hi.y): every part grows
// as the box does, so atomicMax merges the workgroups' boxes into one, from
// all zeros (filled before this pass: an empty box).
layout(std430, set = 0, binding = 9) buffer ObjectBoxes { uvec4 object_boxes[]; };

shared ivec2 group_lo[64], group_hi[64];

void main() {
    const uint object = gl_WorkGroupID.y, chunk = gl_GlobalInvocationID.x;
    const LineRange o = objects[object];
    const ivec2 size = ivec2(push.size);
    // [chunk-box]
    // The box of every visible line in the chunk, on the screen (an empty
    // box is lo = size, hi = -1, which min and max leave alone). A line's walk (walk.glsl)
    // stays within the pixels its ends fall in, give or take rounding: one
    // pixel of slack covers that, more for ends far off the screen, whose
    // coordinates carry less precision.
    ivec2 lo = size, hi = ivec2(-1);
    if (chunk < o.chunk_count) {
        const uint first = o.first_line + chunk * CHUNK;
        const uint end = min(first + CHUNK, o.first_line + o.line_count);
        for (uint line = first; line < end; ++line) {
            const Projected a = projected[ends[2u * line]], b = projected[ends[2u * line + 1u]];
            if ((a.colour >> 24) == 0u || (b.colour >> 24) == 0u) continue;  // not drawn
            const vec2 p0 = (a.xy * 0.5 + 0.5) * vec2(size), p1 = (b.xy * 0.5 + 0.5) * vec2(size);
            const vec2 far = max(abs(p0), abs(p1));
            const float slack = 1.0 + max(far.x, far.y) / 1048576.0;
            const ivec2 line_lo = max(ivec2(clamp(floor(min(p0, p1) - slack), -1.0, 65535.0)), 0);
            const ivec2 line_hi = min(ivec2(clamp(floor(max(p0, p1) + slack), -1.0, 65535.0)), size - 1);
            if (any(greaterThan(line_lo, line_hi))) continue;  // off the screen
            lo = min(lo, line_lo);
            hi = max(hi, line_hi);
        }
        chunk_boxes[o.first_chunk + chunk] = pack_box(lo, hi);
    }
    // [/chunk-box]
    // The workgroup's chunks (all of one object) merged by its first
    // invocation, then into the object's box with one atomicMax per part.
    group_lo[gl_LocalInvocationID.x] = lo;
    group_hi[gl_LocalInvocationID.x] = hi;
    barrier();
    if (gl_LocalInvocationID.x != 0u) return;
    for (uint k = 1u; k < gl_WorkGroupSize.x; ++k) {
        lo = min(lo, group_lo[k]);
        hi = max(hi, group_hi[k]);
    }
    if (any(greaterThan(lo, hi))) return;  // nothing of this object on the screen here
    atomicMax(object_boxes[object].x, 0xffffu - uint(lo.x));
    atomicMax(object_boxes[object].y, 0xffffu - uint(lo.y));
    atomicMax(object_boxes[object].z, uint(hi.x));
    atomicMax(object_boxes[object].w, uint(hi.y));
}
