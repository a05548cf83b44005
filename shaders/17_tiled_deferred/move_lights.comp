#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 17: the lights move on the GPU. One invocation per light: its home
// (the centre of its circle, with its radius, colour and intensity) and its
// path (speed and phase), uploaded once, give where it is at this frame's
// time, written into the buffer every later pass reads as `lights`. The CPU's
// twin is vkt::deferred::MovingLights::write, which --verify compares with.
#include "lighting.glsl"

layout(local_size_x = 256) in;

// [move]
layout(push_constant, std430) uniform MovePush {
    float time;   // seconds, the frame's
    uint count;   // lights
} move;

struct Path {
    float speed, phase;  // the angle at time t: speed * t + phase, phase in [0, 2 pi)
};

layout(set = 0, binding = 0, std430) readonly buffer Homes { PointLight homes[]; };
layout(set = 0, binding = 1, std430) readonly buffer Paths { Path paths[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Lights { PointLight lights[]; };

const float PATH_RADIUS = 0.6;  // MovingLights::path_radius

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= move.count) return;
    float spin = paths[i].speed * move.time + paths[i].phase;
    PointLight light = homes[i];
    light.position += PATH_RADIUS * vec3(cos(spin), 0.0, sin(spin));
    lights[i] = light;
}
// [/move]
