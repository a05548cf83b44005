#version 450
// Chapter 20, --raster binned, pass 1 of 3: each object's box on the screen,
// the pixels its lines may touch. Laid out as the transform pass: row y of
// the dispatch is the object, x its vertices, 64 to a workgroup; each
// workgroup merges its vertices' box into the object's.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

layout(local_size_x = 64) in;
struct Object {
    uint first_vertex, vertex_count, first_out;
    float inv_radius;
};
layout(std430, set = 0, binding = 1) readonly buffer Objects { Object objects[]; };
layout(std430, set = 0, binding = 3) readonly buffer In { Projected projected[]; };
#include "bins.glsl"

shared ivec2 group_lo[64], group_hi[64];

void main() {
    const uint object = gl_WorkGroupID.y, v = gl_GlobalInvocationID.x;
    const Object o = objects[object];
    const ivec2 size = ivec2(push.size);
    // [vertex-box]
    // A line lies between its ends, so the box of an object's visible
    // vertices holds every line of it that is drawn (lines with an end
    // behind the eye are not). The walk (walk.glsl) picks pixels within one
    // pixel of the line, give or take rounding: a pixel of slack each way,
    // more for a vertex far off the screen, whose coordinates carry less
    // precision. An empty box is lo = size, hi = -1: min and max leave it.
    ivec2 lo = size, hi = ivec2(-1);
    if (v < o.vertex_count) {
        const Projected p = projected[o.first_out + v];
        if ((p.colour >> 24) != 0u) {
            const vec2 at = (p.xy * 0.5 + 0.5) * vec2(size);
            const float slack = 1.0 + max(abs(at.x), abs(at.y)) / 1048576.0;
            lo = max(ivec2(clamp(floor(at - slack), -1.0, 65535.0)), 0);
            hi = min(ivec2(clamp(floor(at + slack), -1.0, 65535.0)), size - 1);
        }
    }
    // [/vertex-box]
    group_lo[gl_LocalInvocationID.x] = lo;
    group_hi[gl_LocalInvocationID.x] = hi;
    barrier();
    if (gl_LocalInvocationID.x != 0u) return;
    for (uint k = 1u; k < gl_WorkGroupSize.x; ++k) {
        lo = min(lo, group_lo[k]);
        hi = max(hi, group_hi[k]);
    }
    if (any(greaterThan(lo, hi))) return;  // none of these vertices on the screen
    atomicMax(boxes[object].x, 0xffffu - uint(lo.x));
    atomicMax(boxes[object].y, 0xffffu - uint(lo.y));
    atomicMax(boxes[object].z, uint(hi.x));
    atomicMax(boxes[object].w, uint(hi.y));
}
