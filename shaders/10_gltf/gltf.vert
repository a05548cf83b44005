#version 450
// The loader's vertex (vkt::GltfVertex): position, normal, texture coordinate.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

// [push-constants]
// Per draw (DrawConstants in main.cpp): the node's world matrix, already
// multiplied by the camera's view and projection, and the matrix for normals.
layout(push_constant) uniform Draw {
    mat4 clip_from_object;
    mat4 normal_matrix;
} draw;
// [/push-constants]

layout(location = 0) out vec3 world_normal;
layout(location = 1) out vec2 texcoord;

void main() {
    gl_Position = draw.clip_from_object * vec4(position, 1.0);
    world_normal = mat3(draw.normal_matrix) * normal;
    texcoord = uv;
}
