#pragma once
// Sleeping, taught by chapter 14: a heap of boxes at rest costs nothing. The
// moving bodies that touch each other (through chains of contacts) form an
// island; when every body of an island has been slow for long enough, the
// whole island sleeps: its velocities are zeroed and the world stops
// simulating it. Something awake that touches one of its bodies wakes the
// whole island again. Islands, not single bodies: a box asleep under an awake
// one would be a floor that never gives way.
//
// Plain C++ and glm: no Vulkan here.

#include "vkt/domains/physics_body.hpp"
#include "vkt/domains/physics_collision.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace vkt::physics {

// [sleep-settings]
struct SleepSettings {
    bool enabled = true;
    // m/s: a body rests while |v| + |w| r is below this, r its half diagonal:
    // no point of it moves faster (Box2D's measure).
    float speed = 0.05f;
    // metres: and while no point of it has moved further than this from
    // where it was when its rest began (Jolt's idea). Slow is not still: a
    // stack swaying slowly is slow for half a second at each end of its swing.
    float distance = 0.002f;
    float time = 0.5f;  // seconds an island's every body must rest before it sleeps
};
// [/sleep-settings]

class Islands {
public:
    // After a step: count the time each moving body has rested, find the
    // islands of moving bodies (static ones join none: the floor would make
    // everything one island), and put to sleep each island whose bodies have
    // all rested for settings.time. Returns how many bodies fell asleep.
    uint32_t update(std::span<Body> bodies, std::span<const Manifold> manifolds,
                    const SleepSettings& settings, float dt);

    // Wakes every sleeping body of the islands named (Body::island) in
    // `islands`, which this sorts.
    static void wake(std::span<Body> bodies, std::vector<uint32_t>& islands);

private:
    uint32_t find(uint32_t i);
    std::vector<uint32_t> parent_;  // union-find: each island's root is its lowest index
    std::vector<float> rested_;     // per root: the shortest rest of any of its bodies
    struct Anchor {
        Pose pose;         // where the body was when its rest began (or `time` ago)
        float age = 0.0f;  // seconds since
    };
    std::vector<Anchor> anchors_;  // per body
};

}  // namespace vkt::physics
