#pragma once
// Chapter 14's scenes, built in a World (physics.hpp): the floor and the
// ramp, boxes of several sizes dropped in heaps with random orientations, and
// the two stacks that test a solver, a pyramid and a tall tower. Deterministic:
// the same arguments give the same world on every run and every platform
// (no C library sine or cosine: see portable_sin in physics_scene.cpp).
//
// Plain C++ and glm: no Vulkan here.

#include "vkt/domains/physics.hpp"

#include <cstdint>

namespace vkt::physics {

// A small generator of our own (xorshift32): the same numbers on every
// platform, unlike std::uniform_real_distribution.
struct Random {
    uint32_t state;
    float operator()(float low, float high) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return low + (high - low) * float(state >> 8) * (1.0f / 16777216.0f);
    }
};

// A uniformly random orientation (Shoemake's method: three uniform numbers
// make a unit quaternion, every rotation equally likely).
glm::quat random_orientation(Random& random);

// The ramp of chapter 14's scene: its slope in degrees, below atan(0.5) =
// 26.6 degrees, so boxes with friction 0.5 that come to rest on it stay.
constexpr float kRampDegrees = 20.0f;

struct Scene {
    float floor_half_width = 0.0f;  // the floor's top face is at y = 0
    float extent = 0.0f;            // the boxes start within +-extent along x and z
    uint32_t ramp = 0;              // the ramp's body index
};

// A static floor (body 0, top face at y = 0), a static ramp (body 1), and
// `count` boxes (half extents 0.15 to 0.45 m each way) in four loose heaps in
// the air, square layers narrowing upwards, one above the ramp; each box
// turned at random, all at rest. They fall, tumble and settle into heaps.
Scene add_falling_boxes(World& world, uint32_t count, uint32_t seed = 14);

// A pyramid of `levels` rows of cubes of half size `half`, standing on y = 0
// along x around `base` (its x and z), each row on the one below, rows
// exactly touching, cubes in a row `gap` apart. levels = 10: 55 cubes.
void add_pyramid(World& world, glm::vec3 base, int levels, float half, float gap,
                 float density = 500.0f);

// A tower of `count` boxes of half extents `half`, one on another, standing
// on y = 0 at `base` (its x and z).
void add_tower(World& world, glm::vec3 base, int count, glm::vec3 half, float density = 500.0f);

// Chapter 14's key and --stacks flag: a 10-level pyramid and a 20-box tower,
// on the floor beside the heaps.
void add_stacks(World& world, const Scene& scene);

}  // namespace vkt::physics
