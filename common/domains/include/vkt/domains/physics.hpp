#pragma once
// Rigid boxes under gravity, taught by chapter 14: axis-aligned boxes (they
// never rotate, so a box's AABB is the box itself and every test below is
// exact), a broad phase that finds the overlapping pairs (brute force, n^2,
// or sort-and-sweep along x), a narrow phase that finds the axis of least
// penetration, and sequential impulses with restitution and Coulomb friction,
// warm started from the previous step, plus positional correction with a
// slop. One call to World::step advances the world by one fixed time step.
//
// Plain C++ and glm: no Vulkan here. The same inputs give bit-equal results
// (no threads, no unordered containers, every ordering broken by index).

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace vkt::physics {

struct Body {
    glm::vec3 position{0.0f};      // the centre, metres
    glm::vec3 half_extents{0.5f};  // half the size along x, y and z
    glm::vec3 velocity{0.0f};      // metres per second
    float inverse_mass = 0.0f;     // 1 / kg; 0: static (the floor, walls), never moves
};
static_assert(sizeof(Body) == 10 * sizeof(float), "no padding: the tests memcmp bodies");

// Two boxes overlap when their extents overlap on all three axes, by more
// than zero: boxes whose faces only touch do not.
bool overlaps(const Body& a, const Body& b);

// The narrow phase. Where a and b overlap, the axis along which they overlap
// least is the cheapest way apart: moving b by `depth` along `normal` (a unit
// axis vector pointing from a towards b) separates them. Ties go to the lower
// axis (x before y before z); a centre difference of exactly 0 on the chosen
// axis points the normal along +axis.
struct Penetration {
    int axis = 0;     // 0 x, 1 y, 2 z
    float sign = 1;   // +1 or -1: the normal is sign * (unit vector of axis)
    float depth = 0;  // > 0
    glm::vec3 normal() const {
        glm::vec3 n(0.0f);
        n[axis] = sign;
        return n;
    }
};
std::optional<Penetration> penetration(const Body& a, const Body& b);

// A pair of bodies that may touch: a < b. At least one of them moves
// (two static bodies never need a contact).
struct Pair {
    uint32_t a = 0, b = 0;
    auto operator<=>(const Pair&) const = default;
};

// Every overlapping pair, sorted by (a, b): n(n - 1) / 2 tests. The reference.
std::vector<Pair> find_pairs_brute_force(std::span<const Body> bodies);

// The same pairs, sorted the same way, by sort-and-sweep: sort the boxes by
// their lowest x, walk them in that order, and test each box only against the
// boxes that start before it ends along x. `order` is scratch space (kept by
// the caller so it is not reallocated each step).
std::vector<Pair> find_pairs_sweep(std::span<const Body> bodies, std::vector<uint32_t>& order);

enum class BroadPhase { brute_force, sweep_and_prune };

struct Settings {
    float time_step = 1.0f / 120.0f;  // seconds per step: fixed, whatever the frame rate
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};
    float restitution = 0.2f;            // 0: no bounce, 1: elastic
    float friction = 0.5f;               // Coulomb coefficient: |tangent impulse| <= mu * normal
    float restitution_threshold = 1.0f;  // m/s: slower impacts do not bounce (rest, not jitter)
    int iterations = 10;                 // sequential-impulse passes over all contacts
    float slop = 0.005f;          // metres of penetration left alone (keeps resting contacts alive)
    float percent = 0.4f;         // of the rest, the share pushed apart each step
    bool warm_start = true;       // start each contact from last step's impulse...
    float resting_speed = 0.01f;  // ...unless it is parting faster than this (m/s) or bouncing
    BroadPhase broad_phase = BroadPhase::sweep_and_prune;
};

class World {
public:
    explicit World(const Settings& settings = {}) : settings_(settings) {}

    // A box of the given density (kg per cubic metre); density 0 makes it
    // static. Returns its index.
    uint32_t add_box(glm::vec3 position, glm::vec3 half_extents, float density,
                     glm::vec3 velocity = glm::vec3(0.0f));

    // One fixed step: gravity, broad phase, narrow phase, impulses,
    // integration, positional correction.
    void step();

    std::span<const Body> bodies() const { return bodies_; }
    std::span<Body> bodies() { return bodies_; }
    Settings& settings() { return settings_; }
    const Settings& settings() const { return settings_; }
    // Contacts in the last step (pairs that overlapped).
    std::size_t contact_count() const { return contacts_.size(); }
    // Sum of m v^2 / 2 over the moving bodies.
    double kinetic_energy() const;

private:
    struct Contact {
        Pair pair;
        Penetration along;
        float mass = 0;                   // 1 / (1/m_a + 1/m_b): the pair's effective mass
        float approach = 0;               // normal velocity before the impulses (< 0: closing)
        float target = 0;                 // the normal velocity wanted after the impulses
        float normal_impulse = 0;         // accumulated this step (>= 0)
        glm::vec2 tangent_impulse{0.0f};  // along the two other axes
    };
    void apply(const Contact& contact, float normal, glm::vec2 tangent);
    void solve(Contact& contact);
    void solve_contacts();

    Settings settings_;
    std::vector<Body> bodies_;
    std::vector<Contact> contacts_;  // this step's, sorted by pair: warm start for the next
    std::vector<Contact> previous_;
    std::vector<uint32_t> order_;  // sort-and-sweep scratch
};

// Chapter 14's scene: a static floor (body 0, top face at y = 0, 40 m square
// or wider for large counts) and `count` boxes of random sizes (half extents
// 0.2 to 0.5 m) in columns ten boxes high above it, each column slightly
// jittered, all at rest. Deterministic: the same count and seed give the same
// world. Returns the floor's half width.
float add_falling_boxes(World& world, uint32_t count, uint32_t seed = 14);

}  // namespace vkt::physics
