#version 460
#extension GL_EXT_ray_tracing : require
#extension GL_GOOGLE_include_directive : require
// Chapter 25: a ray that hits nothing sees the sky.
#include "ray_common.glsl"

// [sky]
layout(location = 0) rayPayloadInEXT Hit hit;

void main() {
    const float up = clamp(gl_WorldRayDirectionEXT.y, 0.0, 1.0);
    hit.colour = mix(vec3(0.75, 0.82, 0.9), vec3(0.25, 0.45, 0.8), up);
}
// [/sky]
