#version 450
// [push-block]
// The per-draw values, the same 40 bytes as the C++ struct PushConstants. A
// push_constant block is laid out by std430 rules: vec4 at 0, the mat2's two
// columns at 16 and 24 (8 bytes apart), the vec2 at 32.
layout(push_constant, std430) uniform Push {
    vec4 colour;     // linear RGB; a is unused
    mat2 transform;  // rotation, scale and the aspect correction
    vec2 offset;     // where the object's centre goes, in clip space
} object;
// [/push-block]

layout(location = 0) in vec2 position;  // the shape, radius 1 around (0, 0)
layout(location = 1) in vec3 shade;     // white at the centre, grey at the rim

layout(location = 0) out vec3 colour;

void main() {
    // [transform]
    gl_Position = vec4(object.transform * position + object.offset, 0.0, 1.0);
    // [/transform]
    colour = shade;
}
