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
    float c = cos(o.position_yaw.w), s = sin(o.position_yaw.w);
    vec3 p = position * o.scale.xyz;
    vec3 world = o.position_yaw.xyz + vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
    gl_Position = push.clip_from_world * vec4(world, 1.0);
    // A scale differs along the axes (the walls): the normal scales by its inverse.
    vec3 n = normal / o.scale.xyz;
    world_normal = vec3(c * n.x + s * n.z, n.y, -s * n.x + c * n.z);
    colour = o.colour.rgb;
}
