#version 460

// Chapter 27's objects: chapter 12's lit shapes, one draw each. What a draw
// needs arrives in push constants, which each worker thread records into its
// own secondary command buffer before the object's draw.

// [push]
layout(push_constant) uniform Push {
    mat4 clip_from_object;  // projection * view * model, multiplied on the CPU
    vec4 colour;            // linear RGB; w unused
    vec2 turn;              // cos and sin of the object's turn about +y
} push;
// [/push]

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 world_normal;
layout(location = 1) out vec3 colour;

void main() {
    gl_Position = push.clip_from_object * vec4(position, 1.0);
    // The objects only turn about +y and scale alike in x and z (the floor
    // too, whose normal is +y), so the world normal is the turned one.
    float c = push.turn.x, s = push.turn.y;
    world_normal = vec3(c * normal.x + s * normal.z, normal.y, -s * normal.x + c * normal.z);
    colour = push.colour.rgb;
}
