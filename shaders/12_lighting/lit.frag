#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 12: per fragment (Phong shading), light every pixel with the
// interpolated position and normal; per vertex, take the interpolated colour.
#include "blocks.glsl"

// [fragment]
layout(constant_id = 0) const bool PER_FRAGMENT = true;

layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) in vec3 vertex_colour;

layout(location = 0) out vec4 target;

void main() {
    // shade() normalises: an interpolated normal is shorter than 1 between
    // vertices whose normals differ.
    vec3 colour = PER_FRAGMENT ? surface_colour(world_position, world_normal)
                               : vertex_colour;
    target = vec4(colour, 1.0);
}
// [/fragment]
