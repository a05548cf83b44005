#version 450
// The scene is stored in world coordinates, so one matrix takes it to clip
// space: projection * view, in a push constant, recomputed every frame from
// the camera's pose.
layout(push_constant, std430) uniform Push {
    mat4 clip_from_world;
} push;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;

layout(location = 0) out vec3 out_colour;

void main() {
    gl_Position = push.clip_from_world * vec4(position, 1.0);
    out_colour = colour;
}
