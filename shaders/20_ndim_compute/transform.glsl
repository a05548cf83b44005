// Chapter 20: the transform pass, compiled twice: transform.comp, and
// transform_boxes.comp for --raster binned, which also merges each object's
// box on the screen (BOXES). Two modules rather than one with a switch: a
// pipeline may only use descriptors that are written, and the box buffer
// (set 2, BinnedRaster's) exists only with --raster binned.
#include "ndim.glsl"

// The workgroup's size, chosen by main.cpp: 128 on a GPU, 64 on a CPU device.
layout(local_size_x_id = 2) in;
// The dimension n, fixed when the pipeline is built: the loops below unroll
// and the point fits in registers.
layout(constant_id = 0) const int N = 4;
// Whether each invocation keeps its own copy of the pose (a CPU device).
layout(constant_id = 1) const bool OWN_COPY = false;

struct Object {
    uint first_vertex;  // of its mesh, in coords (units of N floats)
    uint vertex_count;
    uint first_out;     // its first vertex in `projected`
    float inv_radius;   // 1 / the mesh's radius: scales the depth colour
};
// Set 0, TransformPass's (transform_pass.hpp): coords_binding, objects_binding,
// poses_binding, projected_binding.
layout(std430, set = 0, binding = 0) readonly buffer Coords { float coords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Objects { Object objects[]; };
// Per object, N * N + N floats written by the pose pass each frame
// (pose.comp): the matrix M = R * diag(scale), row-major, then the position.
layout(std430, set = 0, binding = 2) readonly buffer Poses { float poses[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Out { Projected projected[]; };
#ifdef BOXES
#include "bins.glsl"
#endif

// [pose-rows]
// This workgroup's object's pose, read from memory once per workgroup: the
// rows of M, each padded with zeros to whole vec4s, then p. A GPU reads
// shared memory 16 bytes at a time as cheaply as 4, and every invocation
// reads the whole matrix for each vertex: vec4s take a quarter of the loads.
const int Q = (N + 3) / 4;  // vec4s per row
shared vec4 pose[N * Q + Q];
// [/pose-rows]
#ifdef BOXES
// The workgroup's box, merged from its subgroups' (bins.glsl's order:
// 0xffff - lo.x, 0xffff - lo.y, hi.x, hi.y; all zeros is empty).
shared uint group_box[4];
#endif

void main() {
    const uint object = gl_WorkGroupID.y;
    const Object o = objects[object];

    // [transform]
    // Every invocation of a workgroup works on the same object: they copy its
    // M and p into shared memory together, then wait for each other (before
    // any of them may leave: barrier() must be reached by all).
    const uint base = object * uint(N * N + N);
    for (uint i = gl_LocalInvocationID.x; i < uint(N * Q + Q); i += gl_WorkGroupSize.x) {
        const uint row = i / uint(Q), first = (i % uint(Q)) * 4u;
        const uint at = base + (row < uint(N) ? row * uint(N) : uint(N * N));
        vec4 v = vec4(0.0);
        for (uint k = 0u; k < 4u; ++k)
            if (first + k < uint(N)) v[k] = poses[at + first + k];
        pose[i] = v;
    }
#ifdef BOXES
    if (gl_LocalInvocationID.x < 4u) group_box[gl_LocalInvocationID.x] = 0u;
#endif
    barrier();
    // [/transform]
    // [own-copy]
    // One vertex per invocation on a GPU, which reads the pose from shared
    // memory as it goes. On a CPU device the dispatch is narrower and each
    // invocation walks several vertices, a dispatch row apart, with its own
    // copy m of the pose, read once for all of them (tuning.hpp chooses).
    vec4 m[N * Q + Q];
    if (OWN_COPY)
        for (int i = 0; i < N * Q + Q; ++i) m[i] = pose[i];
#define M(i) (OWN_COPY ? m[i] : pose[i])
    // [/own-copy]
    // [transform-vertex]
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
#ifdef BOXES
    ivec2 box_lo = ivec2(push.size), box_hi = ivec2(-1);  // empty
#endif
    for (uint v = gl_GlobalInvocationID.x; v < o.vertex_count; v += stride) {
        // x' = p + M x: N * N multiply-adds with the matrix pose.comp built
        // once for the whole object. No sine, no cosine, no plane loop.
        const uint source = (o.first_vertex + v) * uint(N);
        float x[N];
        float point[N];
        for (int c = 0; c < N; ++c) point[c] = coords[source + uint(c)];
        for (int r = 0; r < N; ++r) {
            float sum = M(N * Q + r / 4)[r % 4];
            for (int q = 0; q < Q; ++q) {
                const vec4 row = M(r * Q + q);
                for (int k = 0; k < 4 && 4 * q + k < N; ++k) sum += row[k] * point[4 * q + k];
            }
            x[r] = sum;
        }
        const float depth = (x[N - 1] - M(N * Q + (N - 1) / 4)[(N - 1) % 4]) * o.inv_radius;
        // [/transform-vertex]

        // [project]
        // Down to 2D one dimension at a time, as vkt::ndim::project_to_2d:
        // one running factor f carries every step; a point at or behind the
        // eye is marked (alpha 0) and its lines are left out.
        float f = 1.0;
        bool visible = true;
        if (push.orthographic == 0u)
            for (int k = N - 1; k >= 2; --k) {
                const float distance = push.eye - f * x[k];
                if (!(distance > 0.0)) {
                    visible = false;
                    break;
                }
                f *= push.eye / distance;
            }
        Projected p;
        p.xy = visible ? vec2(f * x[0], f * x[1]) * push.to_clip : vec2(0.0);
        p.colour = visible ? packUnorm4x8(vec4(depth_colour(depth), 1.0)) : 0u;
        p.depth = depth;
        projected[o.first_out + v] = p;
        // [/project]
#ifdef BOXES
        vertex_box(p, box_lo, box_hi);
#endif
    }
#ifdef BOXES
    // [group-box]
    // The box of this workgroup's vertices: merged across each subgroup
    // (subgroupMin and subgroupMax, no memory), then across the subgroups in
    // shared memory, then into the object's box with one atomicMax per side.
    {
        box_lo = subgroupMin(box_lo);
        box_hi = subgroupMax(box_hi);
        if (subgroupElect() && all(lessThanEqual(box_lo, box_hi))) {
            atomicMax(group_box[0], 0xffffu - uint(box_lo.x));
            atomicMax(group_box[1], 0xffffu - uint(box_lo.y));
            atomicMax(group_box[2], uint(box_hi.x));
            atomicMax(group_box[3], uint(box_hi.y));
        }
        barrier();
        // One invocation merges the workgroup's box into the object's (no
        // vertex of the workgroup on the screen: all zeros, nothing to merge).
        if (gl_LocalInvocationID.x == 0u && group_box[0] != 0u)
            for (uint k = 0u; k < 4u; ++k) atomicMax(boxes[object][k], group_box[k]);
    }
    // [/group-box]
#endif
}
