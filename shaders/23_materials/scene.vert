#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23: world position, normal, tangent and texture coordinates.
#include "blocks.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec4 tangent;  // w: the bitangent's sign; 0: none in the file

layout(location = 0) out vec3 world;
layout(location = 1) out vec3 world_normal;
layout(location = 2) out vec2 out_uv;
layout(location = 3) out vec4 world_tangent;

void main() {
    world = (draw.world_from_object * vec4(position, 1.0)).xyz;
    world_normal = transpose(inverse(mat3(draw.world_from_object))) * normal;
    world_tangent = vec4(mat3(draw.world_from_object) * tangent.xyz, tangent.w);
    out_uv = uv;
    gl_Position = frame.clip_from_world * vec4(world, 1.0);
}
