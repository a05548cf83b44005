#version 460
#extension GL_EXT_ray_tracing : require
// Chapter 25: a shadow ray that reaches the sky: the point it left is lit.

// [shadow-miss]
layout(location = 0) rayPayloadInEXT uint shadowed;

void main() {
    shadowed = 0;
}
// [/shadow-miss]
