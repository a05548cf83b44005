#version 450
// Chapter 24's --view boxes: box edges given in world space.
layout(push_constant) uniform View {
    mat4 clip_from_world;
} view;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
layout(location = 0) out vec3 line_colour;

void main() {
    line_colour = colour;
    gl_Position = view.clip_from_world * vec4(position, 1.0);
}
