#version 450
// [shadow-vert]
// The shadow pass: positions only, straight into the light's clip space.
layout(push_constant) uniform Draw {
    mat4 clip_from_object;  // the cascade's light_from_world * world_from_object
} draw;

layout(location = 0) in vec3 position;

void main() {
    gl_Position = draw.clip_from_object * vec4(position, 1.0);
}
// [/shadow-vert]
