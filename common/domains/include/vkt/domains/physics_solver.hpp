#pragma once
// The contact solver of chapter 14: sequential impulses at each contact point.
// At every point of every manifold, in a fixed order, a fixed number of times:
// two friction impulses along the contact plane (limited together by
// Coulomb's cone), an impulse along the normal that stops the approach (or
// bounces), and a separate "push" impulse that removes overlap without
// adding speed (split impulses). Each point starts from its impulses of the
// step before (warm starting), matched by feature id. A last pass from the
// ground up (shock propagation) then settles stacks that the passes before
// could not carry down.
//
// Plain C++ and glm: no Vulkan here.

#include "vkt/domains/physics_body.hpp"
#include "vkt/domains/physics_collision.hpp"

#include <span>
#include <vector>

namespace vkt::physics {

struct SolverSettings {
    int iterations = 6;                  // passes over every contact point
    int push_iterations = 3;             // the first of them that also push overlapping boxes apart
    int shock_iterations = 12;           // most passes over a support in the last pass (0: none)
    float restitution = 0.2f;            // 0: no bounce, 1: elastic
    float restitution_threshold = 1.0f;  // m/s: slower impacts do not bounce (rest, not jitter)
    float friction = 0.5f;               // Coulomb: |friction impulse| <= mu * normal impulse
    float slop = 0.002f;                 // metres of overlap the push leaves alone
    float push = 0.2f;                   // share of the overlap beyond the slop removed per step
    bool warm_start = true;
};

class Solver {
public:
    // Solves every manifold with at least one moving body, changing those
    // bodies' velocities, and the manifolds' points' impulses for the next
    // step's warm start. Sleeping bodies count as static. Gravity says which
    // way is up (for the last pass; none without gravity).
    void solve(std::span<Body> bodies, std::span<Manifold> manifolds,
               const SolverSettings& settings, float dt, glm::vec3 gravity);

    // The velocity of the push (split impulses) that body i should move with
    // this step, besides its real velocity. Zero for a body in no contact.
    glm::vec3 push_velocity(uint32_t i) const { return states_[i].push_v; }
    glm::vec3 push_angular_velocity(uint32_t i) const { return states_[i].push_w; }

private:
    // A body as the solver's loops see it: velocities, real and push, and the
    // inverse mass (0 for static and sleeping bodies).
    struct State {
        glm::vec3 v, w, push_v, push_w;
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
        float target;       // the normal velocity wanted: 0 resting, > 0 bouncing, < 0 a gap
        float push_target;  // the normal push velocity wanted: removes overlap
        float push_impulse;
    };
    // [/row]
    struct Contact {
        uint32_t a, b, first, count;
        glm::vec3 normal, tangent[2];
        Manifold* source;
    };
    void prepare(Manifold& manifold, const SolverSettings& settings, float dt);
    static void solve_friction(const Contact& c, Point& p, float friction, State& a, State& b);
    static void solve_normal(const Contact& c, Point& p, State& a, State& b);
    static void solve_push(const Contact& c, Point& p, State& a, State& b);
    void shock_pass(const SolverSettings& settings, glm::vec3 up);

    std::vector<State> states_;
    std::vector<glm::vec3> centres_;
    std::vector<glm::mat3> inverse_inertias_;  // world space
    std::vector<Contact> contacts_;
    std::vector<Point> points_;
    // The shock pass's scratch: levels, the contact graph, the visiting order.
    std::vector<uint32_t> level_, start_, neighbours_, cursor_, queue_;
    std::vector<uint64_t> order_;  // the lower body's level, then the contact's index
    std::vector<float> saved_mass_;
};

// Two directions along the contact plane, perpendicular to the unit normal n
// and to each other: the friction axes.
void tangent_basis(glm::vec3 n, glm::vec3& t1, glm::vec3& t2);

}  // namespace vkt::physics
