#pragma once
// The contact solver of chapter 14: sequential impulses at each contact point,
// in sub-steps with soft contacts (the "soft step"). The step's contacts are
// found once; the solver then cuts the step into a few sub-steps, and in each
// one gives the moving bodies gravity, applies last sub-step's impulses
// (warm starting), solves every point with a soft constraint (a stiff,
// heavily damped spring that also pushes overlapping boxes apart), moves the
// bodies, and solves every point once more without the spring (relaxing, so
// the push adds no speed). Islands that these springs cannot hold (a tall
// support chain, a far heavier load on a light body) take more, shorter
// sub-steps with stiffer springs (physics_need.cpp). After the last
// sub-step, points that were closing fast when the step began are made to
// part at the set restitution.
//
// Plain C++ and glm: no Vulkan here.

#include "vkt/domains/physics_body.hpp"
#include "vkt/domains/physics_collision.hpp"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace vkt::physics {

// [solver-settings]
struct SolverSettings {
    int substeps = 4;                    // sub-steps per step: gravity, solve, move, relax
    int iterations = 2;                  // soft passes over every point per sub-step
    int relax_iterations = 1;            // passes without the spring, after moving
    float contact_hertz = 120.0f;        // the spring, Hz (x2 on static; both <= sub-step rate / 4)
    float damping_ratio = 10.0f;         // far past critical (1): the spring never rings
    float push_speed = 3.0f;             // m/s: the spring pushes overlap apart no faster
    float restitution = 0.2f;            // 0: no bounce, 1: elastic
    float restitution_threshold = 1.0f;  // m/s: slower impacts do not bounce (rest, not jitter)
    float friction = 0.5f;               // Coulomb: |friction impulse| <= mu * normal impulse
    float angular_damping = 0.2f;        // 1/s: spin loses this share of itself per second
    bool warm_start = true;
    // [need-settings]
    // Islands that these springs cannot hold get more, shorter sub-steps and
    // springs as many times stiffer (still a quarter of their rate): a
    // support chain from the ground this many moving bodies tall, or two
    // moving bodies in contact this unequal in mass. 0 sub-steps: none do.
    int stiff_substeps = 16;         // x stiff_iterations soft passes, at 120 Hz x 16 / 4 = 480 Hz
    int stiff_iterations = 4;        // (+ relax_iterations)
    int stiff_height = 12;           // bodies, counted from the one on the ground
    float stiff_mass_ratio = 50.0f;  // heavier / lighter
    // [/need-settings]
};
// [/solver-settings]

class Solver {
public:
    // Advances every moving body by dt: gravity, the contacts of `manifolds`
    // (those with at least one moving body), positions and orientations.
    // Sleeping bodies count as static. Stores the points' impulses in the
    // manifolds for next step's warm start.
    void step(std::span<Body> bodies, std::span<Manifold> manifolds, const SolverSettings& settings,
              float dt, glm::vec3 gravity);
    // How many bodies the last step gave the stiff sub-steps.
    std::size_t stiff_bodies() const { return movers_.size() - normal_movers_; }

private:
    // A body as the solver's loops see it: its velocities, its inverse mass
    // (0 for static and sleeping bodies), and how far it has moved and turned
    // since the step began (the turn as a rotation vector, to first order).
    struct State {
        glm::vec3 v, w, moved, turned;
        float inverse_mass;
    };
    // [row]
    // One direction d at one contact point, ready to solve: the turning parts
    // of d for each body, r x d, and the spin a unit impulse along d gives
    // each, I^-1 (r x d); the effective mass along d; the impulse so far.
    struct Row {
        glm::vec3 ra_d, rb_d;
        glm::vec3 ia_ra_d, ib_rb_d;
        float mass;
        float impulse;
    };
    struct Point {
        Row normal, tangent[2];
        float separation;    // at the step's start: < 0 overlapping, > 0 a gap
        float approach;      // normal velocity at the step's start: < 0 closing
        float most_impulse;  // the largest normal impulse of the step: did it touch?
    };
    // [/row]
    struct Contact {
        uint32_t a, b, first, count;
        glm::vec3 normal, tangent[2];
        bool static_other;  // one side cannot move: a stiffer spring, under the same cap
        Manifold* source;
    };
    // The soft constraint for one sub-step h: how much of the overlap to
    // turn into speed, and how soft the impulse is (Catto's soft step).
    struct Softness {
        float bias_rate, mass_scale, impulse_scale;
    };
    // One set of sub-steps over some islands: their moving bodies and their
    // contacts, cut into `substeps` with `iterations` soft passes each and
    // the spring at `hertz` (capped at a quarter of the sub-step rate).
    struct Group {
        int substeps, iterations;
        float hertz;
        std::span<const uint32_t> movers;
        std::span<const Contact> contacts;
        uint32_t& passes;  // passes made so far: where the next starts
    };
    void prepare(Manifold& manifold, const SolverSettings& settings);
    // Which islands need the stiff sub-steps (physics_need.cpp): fills
    // movers_ (the normal islands' moving bodies, then the stiff ones') and
    // orders contacts_ the same way.
    void find_needs(const SolverSettings& settings);
    void run(std::span<Body> bodies, const Group& group, const SolverSettings& settings, float dt,
             glm::vec3 gravity);
    void solve_contacts(const SolverSettings& settings, const Group& group, float h, bool soft);
    void restitution(const SolverSettings& settings);

    std::vector<State> states_;
    std::vector<glm::vec3> centres_;           // at the step's start
    std::vector<glm::mat3> inverse_inertias_;  // world space, fixed for the step
    std::vector<Contact> contacts_;
    // Passes made over the contacts so far: where each pass starts among a
    // contact's points (solve_contacts says why). One count per group of
    // islands, so that the stiff islands' passes do not move where the
    // others' start (nor change how they move).
    uint32_t passes_[2] = {0, 0};
    std::vector<Point> points_;
    std::vector<std::pair<uint32_t, uint32_t>> bouncing_;  // (contact, point) that bounce this step
    Softness soft_{}, soft_static_{};
    // find_needs' work: per body its island (union-find, the lowest index
    // the root), its support height (0: not on the ground), whether its
    // island is stiff; the contacts between moving bodies as lists per body.
    std::vector<uint32_t> parent_, height_, first_neighbour_, neighbours_, queue_;
    std::vector<uint8_t> stiff_;
    std::vector<uint32_t> movers_;  // moving bodies: the normal islands', then the stiff ones'
    std::size_t normal_movers_ = 0, normal_contacts_ = 0;
};

// Two directions along the contact plane, perpendicular to the unit normal n
// and to each other: the friction axes.
void tangent_basis(glm::vec3 n, glm::vec3& t1, glm::vec3& t2);

// The soft constraint's three numbers for a spring of frequency `hertz` and
// damping ratio `zeta`, solved implicitly over a sub-step h.
void soft_constraint(float hertz, float zeta, float h, float& bias_rate, float& mass_scale,
                     float& impulse_scale);

}  // namespace vkt::physics
