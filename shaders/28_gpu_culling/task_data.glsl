// Chapter 28's task path: the meshlets of the meshes (chapter 26's, built by
// vkt::build_meshlets; task_path.hpp uploads them), in a set of their own,
// and the payload a task workgroup hands its mesh workgroups.

// [task-data]
#include "meshlets/meshlet.glsl"
layout(std430, set = 1, binding = 0) readonly buffer Meshlets { Meshlet meshlets[]; };
layout(std430, set = 1, binding = 1) readonly buffer MeshletVertices { uint meshlet_vertices[]; };
layout(std430, set = 1, binding = 2) readonly buffer MeshletTriangles { uint meshlet_triangles[]; };
layout(std430, set = 1, binding = 3) readonly buffer Vertices { Vertex vertices[]; };

// One task workgroup tests 32 instances (task_path.hpp's kTaskGroup) and
// launches one mesh workgroup for each meshlet of each it keeps; a mesh has
// at most 16 meshlets (kMostMeshlets, checked when they are built). Each
// launch is one word: the instance << 12 | the meshlet.
const uint kTaskGroup = 32, kMostMeshlets = 16, kMeshletBits = 12;
struct Payload {
    uint launch[kTaskGroup * kMostMeshlets];
};
// [/task-data]
