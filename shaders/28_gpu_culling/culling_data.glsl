// Chapter 28's instances, draw lists and push constants, as the cull pass,
// the draws and the pyramid view read them (main.cpp's Push, scene.hpp's
// Instance).

// [push]
layout(push_constant) uniform Push {
    mat4 clip_from_world;
    uint instance_count;  // the culled instances; the floor is instance_count
    uint phase;           // 0: the early pass (or the only one), 1: the late pass
    uint mode;            // 0: cull none, 1: frustum, 2: frustum and occlusion
    uint list;            // the draws: which list's colour (2: the culled, in red)
    uvec2 viewport;       // the depth buffer's size in pixels
    uvec2 pyramid;        // the pyramid's level 0, in texels
    uint levels;          // its mip levels
    uint show_level;      // --view pyramid: which level
    uint meshlet_cull;    // the task path: 1 tests each meshlet (meshlet_cull.glsl)
    uint pad;
    vec3 eye;             // the camera's position in the world (the normal cones)
} push;
// [/push]

struct Instance {
    vec4 position_yaw;
    vec4 scale;
    vec4 colour;
    vec4 box_centre;
    vec4 box_half;  // w: the mesh's index
};
layout(std430, set = 0, binding = 0) readonly buffer Instances { Instance instances[]; };
// Each mesh: its indices (the indirect path) and its meshlets (the task path).
struct Mesh {
    uint first_index, index_count, first_meshlet, meshlet_count;
};
layout(std430, set = 0, binding = 1) readonly buffer Meshes { Mesh meshes[]; };

// The three draw lists: the early pass's, the late pass's, and (--view
// culled) the occluded instances', each instance_count commands long.
const uint EARLY = 0, LATE = 1, CULLED = 2;

// Where instance o puts a vertex of its mesh, and the normal's direction in
// the world: the vertex shader and the task path's mesh shader both call
// this, so that both draw the same triangles to the bit.
void place(Instance o, vec3 position, vec3 normal, out vec4 clip, out vec3 world_normal) {
    float c = cos(o.position_yaw.w), s = sin(o.position_yaw.w);
    vec3 p = position * o.scale.xyz;
    vec3 world = o.position_yaw.xyz + vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
    clip = push.clip_from_world * vec4(world, 1.0);
    // A scale differs along the axes (the walls): the normal scales by its inverse.
    vec3 n = normal / o.scale.xyz;
    world_normal = vec3(c * n.x + s * n.z, n.y, -s * n.x + c * n.z);
}
