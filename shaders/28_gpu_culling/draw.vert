#version 460
#extension GL_GOOGLE_include_directive : require

// Chapter 28's draws: every command's firstInstance is the instance's index,
// so gl_InstanceIndex finds its place, size and colour.

#include "culling_data.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 world_normal;
layout(location = 1) out vec3 colour;

void main() {
    Instance o = instances[gl_InstanceIndex];
    place(o, position, normal, gl_Position, world_normal);
    colour = o.colour.rgb;
}
