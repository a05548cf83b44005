#include "vkt/domains/physics.hpp"

#include <algorithm>
#include <chrono>

namespace vkt::physics {

uint32_t World::add_box(glm::vec3 position, glm::vec3 half_extents, float density,
                        glm::quat orientation, glm::vec3 velocity, glm::vec3 angular_velocity) {
    const float mass = density * 8.0f * half_extents.x * half_extents.y * half_extents.z;
    Body body;
    body.position = position;
    body.orientation = glm::normalize(orientation);
    body.half_extents = half_extents;
    if (mass > 0.0f) {
        body.velocity = velocity;
        body.angular_velocity = angular_velocity;
        body.inverse_mass = 1.0f / mass;
        body.inverse_inertia = box_inverse_inertia(half_extents, mass);
    }
    bodies_.push_back(body);
    return uint32_t(bodies_.size() - 1);
}

std::size_t World::contact_points() const {
    std::size_t n = 0;
    for (const Manifold& m : manifolds_) n += m.count;
    return n;
}

std::size_t World::awake_count() const {
    std::size_t n = 0;
    for (const Body& body : bodies_) n += body.is_active() ? 1 : 0;
    return n;
}

double World::energy() const {
    double sum = 0.0;
    for (const Body& body : bodies_)
        sum += kinetic_energy(body) + potential_energy(body, settings_.gravity);
    return sum;
}

namespace {

// Last step's impulses for the points of `now` that `before` had too (the
// same feature id: the same corner on the same face), for the warm start.
void carry_impulses(const Manifold& before, Manifold& now) {
    for (uint32_t i = 0; i < now.count; ++i)
        for (uint32_t j = 0; j < before.count; ++j)
            if (now.points[i].id == before.points[j].id) {
                now.points[i].normal_impulse = before.points[j].normal_impulse;
                now.points[i].friction_impulse = before.points[j].friction_impulse;
                break;
            }
}

}  // namespace

void World::find_pairs() {
    if (settings_.broad_phase == BroadPhase::brute_force)
        find_pairs_brute_force(aabbs_, bodies_, pairs_);
    else
        sweep_.find_pairs(aabbs_, bodies_, pairs_);
}

// [narrow-phase]
void World::narrow_phase() {
    std::swap(previous_, manifolds_);
    auto asleep = [&](const Manifold& m) {
        return !bodies_[m.a].is_active() && !bodies_[m.b].is_active();
    };
    for (;;) {
        manifolds_.clear();
        to_wake_.clear();
        // Both lists are sorted by pair: one merge walk through them.
        auto old = previous_.begin();
        for (const Pair& pair : pairs_) {
            // A contact between sleepers (or a sleeper and something static)
            // stays as it was, impulses and all, ready for when its island
            // wakes: nothing there has moved.
            for (; old != previous_.end() && Pair{old->a, old->b} < pair; ++old)
                if (asleep(*old)) manifolds_.push_back(*old);
            // Speculative contacts: the margin grows with how far the two
            // can close on each other this step, up to the speculative
            // distance (a gap wider than that is left to the next step, or
            // to the time of impact).
            const float closing = glm::length(bodies_[pair.b].velocity - bodies_[pair.a].velocity);
            const float reach =
                std::min(closing * settings_.time_step, settings_.speculative_distance);
            Manifold m;
            if (!collide(boxes_[pair.a], boxes_[pair.b], settings_.margin + reach, m)) continue;
            m.a = pair.a;
            m.b = pair.b;
            if (old != previous_.end() && old->a == pair.a && old->b == pair.b)
                carry_impulses(*old, m);
            // Something moving touches a sleeper: its island wakes.
            for (uint32_t i : {pair.a, pair.b})
                if (!bodies_[i].is_static() && !bodies_[i].awake)
                    to_wake_.push_back(bodies_[i].island);
            manifolds_.push_back(m);
        }
        for (; old != previous_.end(); ++old)
            if (asleep(*old)) manifolds_.push_back(*old);
        if (to_wake_.empty()) return;
        // Once more with the woken islands awake (their pairs are new to the
        // broad phase), so that their contacts are solved in this very step.
        Islands::wake(bodies_, to_wake_);
        find_pairs();
    }
}
// [/narrow-phase]

// [continuous]
// Box2D's rule for "fast": a body that moved more than half its smallest half
// extent this step might have passed through something thin. Each such body
// is swept from its pose before the solver to its pose after it, against
// every static box near its path; it stops at the first time of impact (its
// velocity kept: next step's contact, found at the margin, stops it).
void World::continuous() {
    statics_.clear();
    for (uint32_t i = 0; i < uint32_t(bodies_.size()); ++i)
        if (bodies_[i].is_static()) statics_.push_back(i);
    for (uint32_t i = 0; i < uint32_t(bodies_.size()); ++i) {
        Body& body = bodies_[i];
        if (!body.is_active()) continue;
        const Pose& from = starts_[i];
        const glm::quat turn = body.orientation * glm::conjugate(from.orientation);
        const float moved =
            glm::length(body.position - from.position) +
            2.0f * glm::length(glm::vec3(turn.x, turn.y, turn.z)) * glm::length(body.half_extents);
        const float smallest =
            std::min({body.half_extents.x, body.half_extents.y, body.half_extents.z});
        if (moved <= 0.5f * smallest) continue;
        const Pose to{body.position, body.orientation};
        // The path's bounds: the box's AABB at each end, joined.
        const OrientedBox end = oriented_box(body);
        const Aabb a0 = aabbs_[i];
        const Aabb a1 = world_aabb(end.centre, end.rotation, end.half_extents, settings_.margin);
        const Aabb path{glm::min(a0.low, a1.low), glm::max(a0.high, a1.high)};
        float first = 1.0f;
        for (uint32_t j : statics_)
            if (overlaps(path, aabbs_[j]))
                first = std::min(first, time_of_impact(boxes_[j], body.half_extents, from, to,
                                                       settings_.margin));
        if (first < 1.0f) {
            body.position = glm::mix(from.position, to.position, first);
            const glm::quat q1 = glm::dot(from.orientation, to.orientation) < 0.0f ? -to.orientation
                                                                                   : to.orientation;
            body.orientation = glm::normalize((1.0f - first) * from.orientation + first * q1);
        }
    }
}
// [/continuous]

// [step]
void World::step() {
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    const Settings& s = settings_;
    const float dt = s.time_step;
    const auto n = uint32_t(bodies_.size());

    // 1. The gyroscopic term, once a step.
    for (Body& body : bodies_)
        if (body.is_active()) gyroscopic_step(body, dt);
    const auto velocities_done = clock::now();

    // 2. Broad phase: each box's axes and world AABB, grown by the margin and
    // by how far it moves this step, then the pairs whose AABBs overlap.
    boxes_.resize(n);
    aabbs_.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
        boxes_[i] = oriented_box(bodies_[i]);
        const float reach =
            s.margin + std::min(glm::length(bodies_[i].velocity) * dt, s.speculative_distance);
        aabbs_[i] = world_aabb(boxes_[i].centre, boxes_[i].rotation, boxes_[i].half_extents, reach);
    }
    find_pairs();
    const auto broad_done = clock::now();

    // 3. Narrow phase: contact manifolds, last step's impulses, waking
    // (before the solver, so woken bodies get this step's gravity).
    narrow_phase();
    const auto narrow_done = clock::now();

    // 4. The sub-steps: gravity, soft contacts, moving, relaxing; then bounces.
    starts_.resize(n);
    for (uint32_t i = 0; i < n; ++i) starts_[i] = {bodies_[i].position, bodies_[i].orientation};
    solver_.step(bodies_, manifolds_, s.solver, dt, s.gravity);
    const auto solver_done = clock::now();

    // 5. Fast bodies stop where they first meet a static body.
    continuous();

    // 6. Islands at rest fall asleep.
    islands_.update(bodies_, manifolds_, s.sleep, dt);
    const auto done = clock::now();

    auto ms = [](clock::duration d) {
        return std::chrono::duration<double, std::milli>(d).count();
    };
    times_ = {ms(broad_done - velocities_done), ms(narrow_done - broad_done),
              ms(solver_done - narrow_done), ms(velocities_done - start) + ms(done - solver_done)};
}
// [/step]

}  // namespace vkt::physics
