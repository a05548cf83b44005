#version 450
layout(location = 0) in vec3 colour;
layout(location = 0) out vec4 out_colour;

void main() {
    // Half-transparent: where many points land on one pixel (the core, the
    // arms) the colour builds up; a lone point is a faint dot.
    out_colour = vec4(colour, 0.5);
}
