#version 460
#extension GL_GOOGLE_include_directive : require
// Chapter 24's lit pass: the world position and normal of each fragment,
// from which its shadow ray starts.
#include "frame.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(location = 0) out vec3 world;
layout(location = 1) out vec3 world_normal;

void main() {
    world = (draw.world_from_object * vec4(position, 1.0)).xyz;
    world_normal = transpose(inverse(mat3(draw.world_from_object))) * normal;
    gl_Position = frame.clip_from_world * vec4(world, 1.0);
}
