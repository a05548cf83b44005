// What init.comp and simulate.comp share: the particle buffer, the push
// constants and the workgroup size.

// [particle-block]
// std430: a struct's alignment is its largest member's (16 bytes for vec4),
// and an array's stride is its element's size rounded up to that alignment.
// Two vec4 make 32 bytes with no padding, matching the C++ struct Particle.
struct Particle {
    vec4 position;  // xyz: where; w: a colour parameter, 0..1
    vec4 velocity;  // xyz: units per second; w: unused
};

// A storage buffer: read and written by the shader, sized at run time (the
// unsized array takes whatever range the descriptor gives it).
layout(std430, set = 0, binding = 0) buffer Particles {
    Particle particles[];
};
// [/particle-block]

// The galaxy's one central mass (the gravitational constant included), and
// what is added to r^2 so that the pull stays finite at the centre.
const float kGM = 1.0;
const float kSoftening = 0.02;

// [push]
// Per dispatch: which particles (a chunk of the buffer, see main.cpp), and
// how far to move them.
layout(push_constant) uniform Push {
    uint first;  // the chunk's first particle in the whole system (for the hash)
    uint count;  // particles in this chunk: the bounds check
    uint steps;  // fixed steps to take this frame (0 or more)
    float dt;    // seconds per step: 1/120
} push;
// [/push]

// [local-size]
// The workgroup size comes from the pipeline (specialization constant 0), so
// C++'s kWorkgroupSize and the shader cannot disagree. 256 is a multiple of
// every GPU's SIMD width (32 or 64); the guaranteed maxComputeWorkGroupSize[0]
// is only 128, so main.cpp checks the device's limit before asking for 256.
layout(local_size_x_id = 0) in;
// [/local-size]
