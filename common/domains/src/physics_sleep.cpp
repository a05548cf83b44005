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
    anchors_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
        Body& body = bodies[i];
        if (!body.is_active()) continue;
        // Judged by the fastest point, not by spin alone: a slowly turning
        // big box moves its corners as fast as a quickly turning small one.
        const float reach = glm::length(body.half_extents);
        bool resting =
            glm::length(body.velocity) + glm::length(body.angular_velocity) * reach < s.speed;
        // And by how far it has got from its anchor, the pose it had when its
        // rest began, taken again every `time` seconds while it rests: no
        // point of the box is further from where it was than the centre's
        // move plus the turn's chord, 2 sin(angle / 2) = 2 |the turn's vector
        // part|, times the half diagonal. Within `distance` of the anchor,
        // the anchor within `distance` of the one before: in any `time`
        // seconds of rest, no point moves more than 3 x `distance`.
        Anchor& anchor = anchors_[i];
        if (resting && body.sleep_time > 0.0f) {
            const glm::quat turn = body.orientation * glm::conjugate(anchor.pose.orientation);
            const float moved = glm::length(body.position - anchor.pose.position) +
                                2.0f * glm::length(glm::vec3(turn.x, turn.y, turn.z)) * reach;
            resting = moved <= s.distance;
        }
        anchor.age = resting && body.sleep_time > 0.0f ? anchor.age + dt : 0.0f;
        if (anchor.age == 0.0f || anchor.age >= s.time)
            anchor = {{body.position, body.orientation}, 0.0f};
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
