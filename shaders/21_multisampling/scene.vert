#version 450
// Chapter 21's scene: flat-coloured geometry in one world plane, placed by
// one matrix per draw; `striped` is 1 on the quad the fragment shader stripes.

layout(push_constant) uniform Draw {
    mat4 clip_from_world;
} draw;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;
layout(location = 2) in float striped;

layout(location = 0) out vec3 out_colour;
layout(location = 1) out float out_striped;

void main() {
    gl_Position = draw.clip_from_world * vec4(position, 1.0);
    out_colour = colour;
    out_striped = striped;
}
