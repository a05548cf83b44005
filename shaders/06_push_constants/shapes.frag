#version 450
// The fragment shader sees the same push constants: it tints the shading with
// the object's colour.
layout(push_constant, std430) uniform Push {
    vec4 colour;
    mat2 transform;
    vec2 offset;
} object;

layout(location = 0) in vec3 shade;
layout(location = 0) out vec4 target;

void main() {
    target = vec4(shade * object.colour.rgb, 1.0);
}
