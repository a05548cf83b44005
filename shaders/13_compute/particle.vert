#version 450
// Chapter 13: each particle is one point. The compute shader's storage
// buffer is bound here as an ordinary vertex buffer: the same bytes, read
// through vertex input.

// [vertex-input]
layout(location = 0) in vec4 position;  // Particle.position: xyz, colour parameter in w
// [/vertex-input]

layout(push_constant) uniform Push {
    mat4 view_projection;
} push;

layout(location = 0) out vec3 out_colour;

void main() {
    gl_Position = push.view_projection * vec4(position.xyz, 1.0);
    // A point list needs gl_PointSize. 1.0 needs no device feature (larger
    // points need largePoints) and is one pixel at any resolution.
    gl_PointSize = 1.0;
    // Warm white at the core, through orange, to blue at the rim (linear RGB).
    const float t = position.w;
    out_colour = t < 0.3 ? mix(vec3(1.0, 0.85, 0.6), vec3(1.0, 0.45, 0.15), t / 0.3)
                         : mix(vec3(1.0, 0.45, 0.15), vec3(0.2, 0.4, 1.0), (t - 0.3) / 0.7);
}
