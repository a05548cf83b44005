#version 450
// [vertex-shader]
// The vertex inputs: one per attribute description, matched by location.
// They are filled from the vertex buffer, a new Vertex for each invocation.
layout(location = 0) in vec2 position;   // Vertex::position, offset 0
layout(location = 1) in vec3 colour_in;  // Vertex::colour, offset 8

layout(location = 0) out vec3 colour;

void main() {
    gl_Position = vec4(position, 0.0, 1.0);
    colour = colour_in;
}
// [/vertex-shader]
