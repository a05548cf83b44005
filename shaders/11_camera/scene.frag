#version 450
// Every face has one colour at all its corners, so it is that colour all over.
layout(location = 0) in vec3 colour;
layout(location = 0) out vec4 target;

void main() {
    target = vec4(colour, 1.0);
}
