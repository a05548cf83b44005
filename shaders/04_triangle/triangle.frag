#version 450
// [fragment-shader]
// The rasteriser interpolates the vertex colours across the triangle.
layout(location = 0) in vec3 colour;
layout(location = 0) out vec4 target;

void main() {
    target = vec4(colour, 1.0);
}
// [/fragment-shader]
