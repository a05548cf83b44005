// Chapter 26's buffers and push constants, as the task, mesh and vertex
// shaders read them (main.cpp's Push, GpuVertex and ch26::Meshlet).

// [push]
layout(push_constant) uniform Push {
    mat4 clip_from_world;
    vec4 eye;           // xyz: the camera, in the world
    vec4 base_colour;   // the model's first material
    uint view;          // 0 lit, 1 meshlets, 2 culled
    uint meshlet_count;
    uint counter_base;  // where this frame's counters start in `counters`
    uint cull;          // 1: cull meshlets in the task shader
} push;
// [/push]

#include "meshlets/meshlet.glsl"

layout(std430, set = 0, binding = 0) readonly buffer Vertices { Vertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Meshlets { Meshlet meshlets[]; };
layout(std430, set = 0, binding = 2) readonly buffer MeshletVertices { uint meshlet_vertices[]; };
layout(std430, set = 0, binding = 3) readonly buffer MeshletTriangles { uint meshlet_triangles[]; };
// Per frame in flight, four counters: meshlets outside the frustum, meshlets
// facing away, triangles sent on to the mesh shader, meshlets sent on.
layout(std430, set = 0, binding = 4) buffer Counters { uint counters[]; };
// --view culled: the second camera the picture is drawn from, per frame in
// flight (the push constants hold the camera the task shader tests for).
layout(std430, set = 0, binding = 5) readonly buffer Shown { mat4 clip_from_world[]; } shown;
const uint COUNTERS_PER_FRAME = 4;  // main.cpp's kCounters: counter_base / 4 is the slot

// The task shader's verdict on a meshlet (the first two are also the
// indices of their counters), and the flat colour --view culled paints a
// culled one (linear; chapter 28's colours for the same two tests).
const uint OUTSIDE = 0, FACING_AWAY = 1, KEPT = 2, VIEW_CULLED = 2;
const vec3 kCulledColour[2] = vec3[2](vec3(0.75, 0.05, 0.85), vec3(1.0, 0.75, 0.0));

// The task shader hands the mesh shader the meshlets it launches, and
// (read only by --view culled) each one's verdict.
const uint kTaskGroup = 32;
struct Payload {
    uint meshlet[kTaskGroup];
    uint verdict[kTaskGroup];
};
