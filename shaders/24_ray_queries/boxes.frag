#version 450
// Chapter 24's --view boxes: each edge in its box's colour.
layout(location = 0) in vec3 line_colour;
layout(location = 0) out vec4 frag_colour;

void main() {
    frag_colour = vec4(line_colour, 1.0);
}
