#version 450
// Each line is its vertices' colour, blended along it: linear values that the
// _SRGB target encodes.
layout(location = 0) in vec3 colour;
layout(location = 0) out vec4 target;

void main() {
    target = vec4(colour, 1.0);
}
