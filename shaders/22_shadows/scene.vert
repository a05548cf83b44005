#version 450
// Chapter 22's lit pass: world position and normal for the fragment shader,
// which looks the position up in the shadow map.
layout(set = 0, binding = 0) uniform Frame {
    mat4 clip_from_world;
    mat4 light_from_world[4];
    vec4 splits;   // the far distance of cascades 0..3
    vec4 eye;      // xyz: the camera's position
    vec4 forward;  // xyz: where it looks
    vec4 light;    // xyz: the direction the light travels
    uvec4 settings;  // x: cascades, y: 1 to colour them
} frame;

layout(push_constant) uniform Draw {
    mat4 world_from_object;
    vec4 colour;
} draw;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(location = 0) out vec3 world;
layout(location = 1) out vec3 world_normal;

void main() {
    world = (draw.world_from_object * vec4(position, 1.0)).xyz;
    // Objects are scaled, rotated about y and moved: the inverse transpose
    // keeps normals perpendicular (chapter 12).
    world_normal = transpose(inverse(mat3(draw.world_from_object))) * normal;
    gl_Position = frame.clip_from_world * vec4(world, 1.0);
}
