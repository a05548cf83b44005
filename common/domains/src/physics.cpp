#include "vkt/domains/physics.hpp"

#include <algorithm>
#include <cmath>

namespace vkt::physics {

bool overlaps(const Body& a, const Body& b) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(b.position[k] - a.position[k]) >= a.half_extents[k] + b.half_extents[k])
            return false;
    return true;
}

std::optional<Penetration> penetration(const Body& a, const Body& b) {
    Penetration best;
    for (int k = 0; k < 3; ++k) {
        const float d = b.position[k] - a.position[k];
        const float depth = a.half_extents[k] + b.half_extents[k] - std::abs(d);
        if (depth <= 0.0f) return std::nullopt;  // apart along this axis: no contact
        if (k == 0 || depth < best.depth) best = {k, d < 0.0f ? -1.0f : 1.0f, depth};
    }
    return best;
}

namespace {
bool both_static(const Body& a, const Body& b) {
    return a.inverse_mass == 0.0f && b.inverse_mass == 0.0f;
}
}  // namespace

std::vector<Pair> find_pairs_brute_force(std::span<const Body> bodies) {
    std::vector<Pair> pairs;
    const auto n = uint32_t(bodies.size());
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            if (!both_static(bodies[i], bodies[j]) && overlaps(bodies[i], bodies[j]))
                pairs.push_back({i, j});
    return pairs;  // already sorted by (a, b)
}

std::vector<Pair> find_pairs_sweep(std::span<const Body> bodies, std::vector<uint32_t>& order) {
    // Sort by the lowest x (ties by index, so the order never depends on the
    // sorting algorithm's whims).
    const auto n = uint32_t(bodies.size());
    order.resize(n);
    for (uint32_t i = 0; i < n; ++i) order[i] = i;
    auto low_x = [&](uint32_t i) { return bodies[i].position.x - bodies[i].half_extents.x; };
    std::sort(order.begin(), order.end(), [&](uint32_t i, uint32_t j) {
        const float xi = low_x(i), xj = low_x(j);
        return xi < xj || (xi == xj && i < j);
    });
    // Sweep: the boxes after i in this order that start before i ends along x
    // are the only ones that can overlap it; the first one that starts at or
    // beyond i's end, and every one after it, cannot.
    std::vector<Pair> pairs;
    for (uint32_t s = 0; s < n; ++s) {
        const uint32_t i = order[s];
        const float high_x = bodies[i].position.x + bodies[i].half_extents.x;
        for (uint32_t t = s + 1; t < n && low_x(order[t]) < high_x; ++t) {
            const uint32_t j = order[t];
            if (!both_static(bodies[i], bodies[j]) && overlaps(bodies[i], bodies[j]))
                pairs.push_back({std::min(i, j), std::max(i, j)});
        }
    }
    std::sort(pairs.begin(), pairs.end());  // the same order as brute force
    return pairs;
}

uint32_t World::add_box(glm::vec3 position, glm::vec3 half_extents, float density,
                        glm::vec3 velocity) {
    const float volume = 8.0f * half_extents.x * half_extents.y * half_extents.z;
    Body body{position, half_extents, density > 0.0f ? velocity : glm::vec3(0.0f),
              density > 0.0f ? 1.0f / (density * volume) : 0.0f};
    bodies_.push_back(body);
    return uint32_t(bodies_.size() - 1);
}

double World::kinetic_energy() const {
    double sum = 0.0;
    for (const Body& body : bodies_)
        if (body.inverse_mass > 0.0f)
            sum += 0.5 * double(glm::dot(body.velocity, body.velocity)) / double(body.inverse_mass);
    return sum;
}

// An impulse `normal` along the contact normal and `tangent` along the two
// other axes, pushing b one way and a the other (Newton's third law).
void World::apply(const Contact& contact, float normal, glm::vec2 tangent) {
    const int axis = contact.along.axis;
    glm::vec3 impulse(0.0f);
    impulse[axis] = normal * contact.along.sign;
    impulse[(axis + 1) % 3] = tangent.x;
    impulse[(axis + 2) % 3] = tangent.y;
    Body& a = bodies_[contact.pair.a];
    Body& b = bodies_[contact.pair.b];
    a.velocity -= a.inverse_mass * impulse;
    b.velocity += b.inverse_mass * impulse;
}

// One visit to one contact: the normal impulse, then friction.
void World::solve(Contact& contact) {
    const Body& a = bodies_[contact.pair.a];
    const Body& b = bodies_[contact.pair.b];
    const int axis = contact.along.axis;
    // Normal: the impulse that brings the normal velocity to the target; the
    // total may only push (>= 0), never pull.
    glm::vec3 relative = b.velocity - a.velocity;
    const float normal_velocity = relative[axis] * contact.along.sign;
    // Never aim to leave faster than the pair now approaches: other contacts
    // may have slowed it since, and sending it off at the old speed would
    // make energy.
    const float target = std::min(contact.target, std::max(-normal_velocity, 0.0f));
    const float total_normal =
        std::max(contact.normal_impulse + contact.mass * (target - normal_velocity), 0.0f);
    const float normal = total_normal - contact.normal_impulse;
    contact.normal_impulse = total_normal;
    apply(contact, normal, glm::vec2(0.0f));

    // Friction: the impulse that stops the sliding, but no larger (in total)
    // than mu times the normal impulse: Coulomb's cone.
    relative = b.velocity - a.velocity;
    const glm::vec2 sliding(relative[(axis + 1) % 3], relative[(axis + 2) % 3]);
    glm::vec2 total_tangent = contact.tangent_impulse - contact.mass * sliding;
    const float limit = settings_.friction * contact.normal_impulse;
    const float length = glm::length(total_tangent);
    if (length > limit) total_tangent *= length > 0.0f ? limit / length : 0.0f;
    const glm::vec2 tangent = total_tangent - contact.tangent_impulse;
    contact.tangent_impulse = total_tangent;
    apply(contact, 0.0f, tangent);
}

// Sequential impulses, warm started: a pair that touched along the same axis
// last step starts from last step's impulses, so a stack's weight need not be
// found again from nothing each step (10 passes cannot carry it down a stack
// of 10). A guess is only a guess: a pair that bounces, or is already parting,
// starts from zero instead, since pushing it apart again would add energy.
void World::solve_contacts() {
    if (settings_.warm_start) {
        auto old = previous_.begin();  // both lists are sorted by pair: one merge walk
        for (Contact& contact : contacts_) {
            while (old != previous_.end() && old->pair < contact.pair) ++old;
            if (old == previous_.end()) break;
            if (old->pair == contact.pair && old->along.axis == contact.along.axis &&
                old->along.sign == contact.along.sign && contact.target == 0.0f &&
                contact.approach <= settings_.resting_speed) {
                contact.normal_impulse = old->normal_impulse;
                contact.tangent_impulse = old->tangent_impulse;
                apply(contact, contact.normal_impulse, contact.tangent_impulse);
            }
        }
    }
    // Every contact, several times over: each pass fixes what the last broke.
    for (int iteration = 0; iteration < settings_.iterations; ++iteration)
        for (Contact& contact : contacts_) solve(contact);
}

void World::step() {
    const Settings& s = settings_;
    const float dt = s.time_step;

    // 1. Forces: gravity changes every moving body's velocity.
    for (Body& body : bodies_)
        if (body.inverse_mass > 0.0f) body.velocity += s.gravity * dt;

    // 2. Broad phase (which pairs may touch) and narrow phase (how).
    const std::vector<Pair> pairs = s.broad_phase == BroadPhase::brute_force
                                        ? find_pairs_brute_force(bodies_)
                                        : find_pairs_sweep(bodies_, order_);
    std::swap(previous_, contacts_);
    contacts_.clear();
    for (const Pair& pair : pairs) {
        const Body& a = bodies_[pair.a];
        const Body& b = bodies_[pair.b];
        const auto along = penetration(a, b);
        if (!along) continue;
        Contact contact{pair, *along, 1.0f / (a.inverse_mass + b.inverse_mass)};
        // Restitution: a pair approaching faster than the threshold should
        // leave at e times that speed; slower ones just stop (resting boxes
        // would otherwise bounce on gravity's small step forever).
        const float approach = (b.velocity - a.velocity)[along->axis] * along->sign;
        contact.approach = approach;
        contact.target = approach < -s.restitution_threshold ? -s.restitution * approach : 0.0f;
        contacts_.push_back(contact);
    }

    // 3. Impulses: restitution, friction, warm starting (above).
    solve_contacts();

    // 5. Integrate: move with the corrected velocities (semi-implicit Euler).
    for (Body& body : bodies_)
        if (body.inverse_mass > 0.0f) body.position += body.velocity * dt;

    // 6. Positional correction: what the velocities could not prevent (boxes
    // already inside each other) is pushed apart directly, a share `percent`
    // of the depth beyond the slop each step, split by inverse mass.
    for (const Contact& contact : contacts_) {
        Body& a = bodies_[contact.pair.a];
        Body& b = bodies_[contact.pair.b];
        const int axis = contact.along.axis;
        const float depth = a.half_extents[axis] + b.half_extents[axis] -
                            (b.position[axis] - a.position[axis]) * contact.along.sign;
        const float push = std::max(depth - s.slop, 0.0f) * s.percent * contact.mass;
        a.position[axis] -= a.inverse_mass * push * contact.along.sign;
        b.position[axis] += b.inverse_mass * push * contact.along.sign;
    }
}

float add_falling_boxes(World& world, uint32_t count, uint32_t seed) {
    // A small generator of our own (xorshift32): the same numbers on every
    // platform, unlike std::uniform_real_distribution.
    uint32_t state = seed * 2654435761u + 1u;
    auto random = [&state](float low, float high) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return low + (high - low) * float(state >> 8) * (1.0f / 16777216.0f);
    };
    constexpr uint32_t levels = 10;
    // Columns 1.2 m apart, levels 1.3 m apart: boxes of at most 1 m (plus
    // jitter) start apart. Odd levels sit half a column over, so they land
    // across two boxes of the level below.
    constexpr float spacing = 1.2f, rise = 1.3f;
    const uint32_t columns = (count + levels - 1) / levels;
    const auto side = uint32_t(std::ceil(std::sqrt(double(columns))));
    const float half_width = std::max(12.0f, 0.5f * spacing * float(side) + 4.0f);
    world.add_box({0.0f, -0.5f, 0.0f}, {half_width, 0.5f, half_width}, 0.0f);  // the floor
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t column = i % columns, level = i / columns;
        const float shift = level % 2 ? 0.5f : 0.0f;
        const float x = (float(column % side) + shift - 0.5f * float(side - 1)) * spacing;
        const float z = (float(column / side) + shift - 0.5f * float(side - 1)) * spacing;
        const glm::vec3 half(random(0.2f, 0.5f), random(0.2f, 0.5f), random(0.2f, 0.5f));
        const glm::vec3 jitter(random(-0.1f, 0.1f), 0.0f, random(-0.1f, 0.1f));
        const float y = 1.0f + float(level) * rise + random(0.0f, 0.2f);
        world.add_box(glm::vec3(x, y, z) + jitter, half, 500.0f);
    }
    return half_width;
}

}  // namespace vkt::physics
