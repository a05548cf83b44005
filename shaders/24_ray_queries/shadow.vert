#version 460
// Chapter 24's shadow map pass (the --shadows map path): positions only,
// into the light's clip space.
layout(push_constant) uniform Draw {
    mat4 clip_from_object;
} draw;

layout(location = 0) in vec3 position;

void main() {
    gl_Position = draw.clip_from_object * vec4(position, 1.0);
}
