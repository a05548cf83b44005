// The n-dimensional transform and projection of chapter 19, shared by the
// drawing shader (lines.vert) and the capture shader of --verify
// (capture.vert), so that what --verify checks is the code that draws.
// The same arithmetic, in the same order, as vkt::ndim's per-plane path
// (common/src/ndim.cpp): scale, turn in each plane (0,1) first, move, then
// project one dimension at a time.

// [spec-constant]
// The dimension n, fixed when the pipeline is created (chapter 19's
// VkSpecializationInfo), not when the shader is compiled: one SPIR-V file for
// every n, and still a constant to the driver's compiler, which can unroll
// the loops below and keep the N floats of a point in registers.
layout(constant_id = 0) const int N = 4;
// Floats per object: position (N), scale (N), one angle per plane.
const int T = N * (N + 3) / 2;
// [/spec-constant]

// [buffers]
// Every mesh's vertices, N floats each: vertex v is coords[v*N .. v*N + N).
layout(set = 0, binding = 0, std430) readonly buffer Vertices {
    float coords[];
};
// This frame's raw transforms, T floats per object, as Transform::packed()
// lays them out: position, then scale, then angles.
layout(set = 0, binding = 1, std430) readonly buffer Transforms {
    float transforms[];
};
// [/buffers]

// [push]
layout(push_constant) uniform Push {
    vec2 to_clip;          // projected units -> clip space (y negated)
    float eye;             // the eye distance d on each last axis
    int orthographic;      // 1: drop coordinates, 0: perspective
    int vertex_count;      // in the vertex buffer (where --verify writes)
    float inverse_radius;  // 1 / the mesh's radius, for the depth colour
    int object;            // this draw's object: which transform
} push;
// [/push]

// [transform-project]
// Vertex `vertex` of object `object`, to clip space. Returns false when the
// point is at or behind an eye (clipped, as project_to_2d). depth: how far
// along the last axis, in radii of the mesh, -1 far .. +1 near.
bool transform_and_project(int vertex, int object, out vec2 clip, out float depth) {
    const int t = object * T;
    float x[N];
    for (int k = 0; k < N; ++k) x[k] = coords[vertex * N + k] * transforms[t + N + k];
    // Each plane in turn: two coordinates change, O(n^2) per vertex, no
    // matrix. Planes in the order (0,1), (0,2), ..., as their angles lie.
    int a = t + 2 * N;
    for (int i = 0; i < N; ++i)
        for (int j = i + 1; j < N; ++j, ++a) {
            const float c = cos(transforms[a]), s = sin(transforms[a]);
            const float xi = x[i], xj = x[j];
            x[i] = c * xi - s * xj;
            x[j] = s * xi + c * xj;
        }
    for (int k = 0; k < N; ++k) x[k] += transforms[t + k];
    depth = (x[N - 1] - transforms[t + N - 1]) * push.inverse_radius;

    // One running factor f for all the remaining coordinates.
    clip = vec2(0.0);
    float f = 1.0;
    if (push.orthographic == 0)
        for (int k = N - 1; k >= 2; --k) {
            const float distance = push.eye - f * x[k];
            if (!(distance > 0.0)) return false;  // at or behind the eye
            f *= push.eye / distance;
        }
    clip = vec2(f * x[0], f * x[1]) * push.to_clip;
    return true;
}
// [/transform-project]
