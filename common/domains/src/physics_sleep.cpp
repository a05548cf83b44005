#include "vkt/domains/physics_sleep.hpp"

#include <algorithm>

namespace vkt::physics {

uint32_t Islands::find(uint32_t i) {
    while (parent_[i] != i) {
        parent_[i] = parent_[parent_[i]];  // path halving: later finds are shorter
        i = parent_[i];
    }
    return i;
}

// [islands]
uint32_t Islands::update(std::span<Body> bodies, std::span<const Manifold> manifolds,
                         const SleepSettings& s, float dt) {
    if (!s.enabled) return 0;
    const auto n = uint32_t(bodies.size());
    for (Body& body : bodies) {
        if (!body.is_active()) continue;
        // Judged by speed, not spin: a slowly turning big box moves its
        // corners as fast as a quickly turning small one.
        const float spin = glm::length(body.angular_velocity) * glm::length(body.half_extents);
        const bool resting = std::max(glm::length(body.velocity), spin) < s.speed;
        body.sleep_time = resting ? body.sleep_time + dt : 0.0f;
    }
    // Union-find over the contacts between moving bodies. The lower root
    // always wins, so each island's root is its lowest body index: the same
    // label on every run.
    parent_.resize(n);
    rested_.assign(n, 1e30f);
    for (uint32_t i = 0; i < n; ++i) parent_[i] = i;
    for (const Manifold& m : manifolds) {
        if (bodies[m.a].is_static() || bodies[m.b].is_static()) continue;
        const uint32_t ra = find(m.a), rb = find(m.b);
        if (ra < rb) parent_[rb] = ra;
        if (rb < ra) parent_[ra] = rb;
    }
    for (uint32_t i = 0; i < n; ++i)
        if (bodies[i].is_active()) {
            const uint32_t root = find(i);
            rested_[root] = std::min(rested_[root], bodies[i].sleep_time);
        }
    uint32_t slept = 0;
    for (uint32_t i = 0; i < n; ++i) {
        Body& body = bodies[i];
        const uint32_t root = find(i);
        if (!body.is_active() || rested_[root] < s.time) continue;
        body.awake = 0;
        body.island = root;
        body.velocity = glm::vec3(0.0f);
        body.angular_velocity = glm::vec3(0.0f);
        ++slept;
    }
    return slept;
}
// [/islands]

void Islands::wake(std::span<Body> bodies, std::vector<uint32_t>& islands) {
    std::sort(islands.begin(), islands.end());
    for (Body& body : bodies)
        if (!body.is_static() && !body.awake &&
            std::binary_search(islands.begin(), islands.end(), body.island)) {
            body.awake = 1;
            body.sleep_time = 0.0f;
        }
}

}  // namespace vkt::physics
