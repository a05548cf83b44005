#version 450
// Chapter 20: transform and project every unique vertex once per frame. One
// invocation per vertex (or a few, on a CPU device): row y of the dispatch
// is the object, x the vertex.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

layout(local_size_x = 64) in;
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
layout(std430, set = 0, binding = 0) readonly buffer Coords { float coords[]; };
layout(std430, set = 0, binding = 1) readonly buffer Objects { Object objects[]; };
// Per object, N * N + N floats written by the CPU each frame: the matrix
// M = R * diag(scale), row-major, then the position.
layout(std430, set = 0, binding = 2) readonly buffer Poses { float poses[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Out { Projected projected[]; };

// This workgroup's object's pose, read from memory once per workgroup.
shared float pose[N * N + N];

void main() {
    const uint object = gl_WorkGroupID.y;
    const Object o = objects[object];

    // [transform]
    // Every invocation of a workgroup works on the same object: they copy its
    // M and p into shared memory together, then wait for each other (before
    // any of them may leave: barrier() must be reached by all).
    for (uint i = gl_LocalInvocationID.x; i < uint(N * N + N); i += gl_WorkGroupSize.x)
        pose[i] = poses[object * uint(N * N + N) + i];
    barrier();
    // One vertex per invocation on a GPU, which reads the pose from shared
    // memory as it goes. On a CPU device the dispatch is narrower and each
    // invocation walks several vertices, a dispatch row apart, with its own
    // copy m of the pose, read once for all of them (main.cpp).
    float m[N * N + N];
    if (OWN_COPY)
        for (int i = 0; i < N * N + N; ++i) m[i] = pose[i];
#define M(i) (OWN_COPY ? m[i] : pose[i])
    const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint v = gl_GlobalInvocationID.x; v < o.vertex_count; v += stride) {
        // x' = p + M x: N * N multiply-adds with the matrix the CPU built
        // once for the whole object. No sine, no cosine, no plane loop.
        const uint source = (o.first_vertex + v) * uint(N);
        float x[N];
        for (int r = 0; r < N; ++r) {
            float sum = M(N * N + r);
            for (int c = 0; c < N; ++c) sum += M(r * N + c) * coords[source + uint(c)];
            x[r] = sum;
        }
        const float depth = (x[N - 1] - M(N * N + N - 1)) * o.inv_radius;
        // [/transform]

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
    }
}
