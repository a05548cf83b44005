#version 450
// Each face has one colour at all four corners, so the interpolated colour is
// that colour everywhere on the face.
layout(location = 0) in vec3 colour;
layout(location = 0) out vec4 target;

void main() {
    target = vec4(colour, 1.0);
}
