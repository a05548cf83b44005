#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 16, --path forward: light every fragment as it is drawn, with the
// same lights and the same shade_all() as the deferred lighting pass.
#include "deferred/blocks.glsl"

// [forward-frag]
layout(location = 0) in vec3 world_position;
layout(location = 1) in vec3 world_normal;
layout(location = 2) flat in uint material;

layout(location = 0) out vec4 target;

void main() {
    vec3 colour = shade_all(world_position, world_normal, frame.materials[material], 0,
                            frame.light_count, 1.0);
    target = vec4(colour, 1.0);
}
// [/forward-frag]
