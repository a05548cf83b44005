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

// The three draw lists: the early pass's, the late pass's, and (--view
// culled) the occluded instances', each instance_count commands long.
const uint EARLY = 0, LATE = 1, CULLED = 2;
