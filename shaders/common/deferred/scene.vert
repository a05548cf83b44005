#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 16: one vertex shader for the G-buffer pass and the forward pass,
// so that both rasterise exactly the same triangles.
#include "blocks.glsl"

// Per draw: 116 bytes of the 128 every device offers.
layout(push_constant, std430) uniform ObjectPush {
    mat4 model;          // 0
    mat3 normal_matrix;  // 64: three columns 16 bytes apart
    uint material;       // 112: index into frame.materials
} object;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 2) flat out uint material;

// The same position, to the last bit, in both pipelines.
invariant gl_Position;

void main() {
    vec4 world = object.model * vec4(position, 1.0);
    world_position = world.xyz;
    world_normal = object.normal_matrix * normal;
    material = object.material;
    gl_Position = frame.proj * frame.view * world;
}
