// Chapter 28's task path: the meshlets of the meshes (chapter 26's, built by
// vkt::build_meshlets; task_path.hpp uploads them), in a set of their own,
// and the payload a task workgroup hands its mesh workgroups.

// [task-data]
#include "meshlets/meshlet.glsl"
layout(std430, set = 1, binding = 0) readonly buffer Meshlets { Meshlet meshlets[]; };
layout(std430, set = 1, binding = 1) readonly buffer MeshletVertices { uint meshlet_vertices[]; };
layout(std430, set = 1, binding = 2) readonly buffer MeshletTriangles { uint meshlet_triangles[]; };
layout(std430, set = 1, binding = 3) readonly buffer Vertices { Vertex vertices[]; };
// --view culled: the camera the tests are made for, while the pass that
// shows their results draws from a second one (push.phase FATES).
layout(std430, set = 1, binding = 4) readonly buffer Tested { mat4 clip_from_world; vec4 eye; } tested;

// One task workgroup tests 32 instances (task_path.hpp's kTaskGroup) and
// launches one mesh workgroup for each meshlet of each it keeps; a mesh has
// at most 16 meshlets (kMostMeshlets, checked when they are built). Launch k
// has slot k in both arrays, 8 bytes: launch[k], the instance << 12 | the
// meshlet; why[k], which test culled it, written and read only in the pass
// of --view culled (the frame's passes leave it unset).
const uint kTaskGroup = 32, kMostMeshlets = 16, kMeshletBits = 12;
struct Payload {
    uint launch[kTaskGroup * kMostMeshlets];
    uint why[kTaskGroup * kMostMeshlets];  // --view culled: each launch's fate
};
// [/task-data]

// Why a meshlet is not launched (KEPT: it is), counts[7 + why]; and the
// flat colour --view culled paints it in (linear).
const uint OUTSIDE = 0, FACING_AWAY = 1, HIDDEN = 2, KEPT = 3;
const uint FATES = 2;  // push.phase of --view culled's pass
const vec3 kFateColour[3] = vec3[3](vec3(0.75, 0.05, 0.85), vec3(1.0, 0.75, 0.0),
                                    vec3(1.0, 0.05, 0.02));
