#version 450
// Chapter 13: one frame of the simulation, every particle in its own
// invocation. Each particle feels only the central mass, so invocation i
// reads and writes particle i and nothing else: updating in place is safe.
#extension GL_GOOGLE_include_directive : require
#include "particles.glsl"

void main() {
    // [bounds-check]
    // The dispatch covers whole workgroups, so up to 255 invocations of the
    // last one have no particle: they must not touch the buffer.
    const uint index = gl_GlobalInvocationID.x;
    if (index >= push.count) return;
    // [/bounds-check]

    // [integrate]
    // Semi-implicit Euler at a fixed step: the new velocity moves the
    // particle. Stable for orbits (it keeps their energy bounded), and the
    // same steps give the same numbers every run.
    Particle p = particles[index];
    for (uint step = 0u; step < push.steps; ++step) {
        const vec3 x = p.position.xyz;
        const float d2 = dot(x, x) + kSoftening;
        const vec3 acceleration = -kGM * x / (d2 * sqrt(d2));
        p.velocity.xyz += acceleration * push.dt;
        p.position.xyz += p.velocity.xyz * push.dt;
    }
    particles[index] = p;
    // [/integrate]
}
