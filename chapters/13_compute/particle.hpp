#pragma once
// Chapter 13's particle as C++ sees it: the mirror of `struct Particle` in
// shaders/13_compute/particles.glsl (std430). tests/unit/test_dispatch.cpp
// checks these offsets against the compiled shader.

#include <glm/glm.hpp>

#include <cstddef>

// [particle-struct]
struct Particle {
    glm::vec4 position;  // xyz: where; w: a colour parameter, 0..1
    glm::vec4 velocity;  // xyz: units per second; w: unused
};
static_assert(sizeof(Particle) == 32 && offsetof(Particle, velocity) == 16);
// [/particle-struct]
