#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 12: one vertex shader for both lighting modes. The specialization
// constant PER_FRAGMENT, fixed when each pipeline is made, picks the mode.
#include "blocks.glsl"

// [vertex]
layout(constant_id = 0) const bool PER_FRAGMENT = true;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(location = 0) out vec3 world_position;
layout(location = 1) out vec3 world_normal;
layout(location = 2) out vec3 vertex_colour;

void main() {
    vec4 world = object.model * vec4(position, 1.0);
    world_position = world.xyz;
    // Not model * normal: see the normal matrix in the book.
    world_normal = object.normal_matrix * normal;
    gl_Position = scene.proj * scene.view * world;
    // Per vertex (Gouraud): light the three corners, let the rasteriser
    // interpolate the colours. Per fragment, this is unused.
    vertex_colour = PER_FRAGMENT ? vec3(0.0) : surface_colour(world_position, world_normal);
}
// [/vertex]
