#version 450
// Chapter 20: a line with an end behind the eye is left out, fragment by
// fragment (its interpolated `hidden` is above 0 everywhere past that end).
layout(location = 0) in vec3 colour;
layout(location = 1) noperspective in float hidden;
layout(location = 0) out vec4 target;

void main() {
    if (hidden > 0.0) discard;
    target = vec4(colour, 1.0);
}
