#version 450
// Chapter 13: the particles' first state, a spiral galaxy, computed from a
// hash of each particle's index: no random numbers, so every run (and every
// device) starts from exactly the same particles.
#extension GL_GOOGLE_include_directive : require
#include "particles.glsl"

// [hash]
// An integer hash (xor-shift and multiply rounds): nearby indices give
// unrelated bits. Integer arithmetic is exact on every GPU.
uint hash(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// A number in [0, 1) from particle i's own stream s: the top 24 bits of the
// hash, which a float holds exactly.
float uniform01(uint i, uint s) {
    return float(hash(i * 4u + s) >> 8) * (1.0 / 16777216.0);
}
// [/hash]

void main() {
    const uint local = gl_GlobalInvocationID.x;
    if (local >= push.count) return;
    const uint i = push.first + local;

    // Three spiral arms: a radius, the arm's angle twisted by the radius, a
    // little scatter across the arm and above or below the disc.
    const float u = uniform01(i, 0u);
    const float r = 0.08 + 1.6 * u;
    const float arm = float(i % 3u) * 2.0943951;  // 2 pi / 3
    const float angle = arm + 2.6 * r + (uniform01(i, 1u) - 0.5) * (0.35 + 0.5 * r);
    const float height = (uniform01(i, 2u) - 0.5) * 0.08;
    const vec3 position = vec3(r * cos(angle), height, r * sin(angle));

    // A circular orbit about the centre: speed^2 / r equals the softened pull
    // GM r / (r^2 + s)^(3/2); a few percent scatter keeps the orbits apart.
    const float d2 = r * r + kSoftening;
    const float speed = sqrt(kGM * r * r / (d2 * sqrt(d2))) * (0.97 + 0.06 * uniform01(i, 3u));
    const vec3 tangent = vec3(-sin(angle), 0.0, cos(angle));

    particles[local].position = vec4(position, u);
    particles[local].velocity = vec4(speed * tangent, 0.0);
}
