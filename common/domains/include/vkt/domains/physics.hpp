#pragma once
// Rigid boxes that turn, taught by chapter 14: the world that puts the parts
// together. One call to World::step advances it by one fixed time step:
//
//   1. the gyroscopic term                             (physics_body.hpp)
//   2. broad phase: AABB pairs by sort-and-sweep      (physics_broadphase.hpp)
//   3. narrow phase: SAT and clipping, feature ids    (physics_collision.hpp)
//   4. sub-steps: gravity, soft contacts, moving,     (physics_solver.hpp)
//      relaxing; then restitution
//   5. fast bodies: time of impact with static ones   (physics_collision.hpp)
//   6. islands that fall asleep                       (physics_sleep.hpp)
//
// Plain C++ and glm: no Vulkan here. The same inputs give bit-equal results
// (no threads, no unordered containers, every ordering broken by index).

#include "vkt/domains/physics_body.hpp"
#include "vkt/domains/physics_broadphase.hpp"
#include "vkt/domains/physics_collision.hpp"
#include "vkt/domains/physics_sleep.hpp"
#include "vkt/domains/physics_solver.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace vkt::physics {

enum class BroadPhase { brute_force, sweep_and_prune };

struct Settings {
    float time_step = 1.0f / 120.0f;  // seconds per step: fixed, whatever the frame rate
    glm::vec3 gravity{0.0f, -9.81f, 0.0f};
    // Boxes closer than this make contacts (with a negative depth: a gap the
    // solver lets close), so a resting box keeps its contacts even where
    // rounding lifts it a hair off the box below.
    float margin = 0.005f;
    // Speculative contacts: each pair's margin grows by how far the two could
    // close on each other in one step, but by no more than this (Box2D's
    // 2 cm): a box that will land this step is caught where it touches, and
    // a fast box passing by is not stopped by a gap it would never close.
    // A faster box is moved back to where it first comes within the margin
    // of a static box (a time-of-impact pass after the solver), so that it
    // meets a thin plate instead of passing it.
    float speculative_distance = 0.02f;
    BroadPhase broad_phase = BroadPhase::sweep_and_prune;
    SolverSettings solver;
    SleepSettings sleep;
};

// Where the last step's time went, in milliseconds.
struct StepTimes {
    // solver: with moving the bodies; other: the velocity step, the time of
    // impact of fast bodies, and sleeping.
    double broad = 0, narrow = 0, solver = 0, other = 0;
    double total() const { return broad + narrow + solver + other; }
};

class World {
public:
    explicit World(const Settings& settings = {}) : settings_(settings) {}

    // A box of the given density (kg per cubic metre); density 0 makes it
    // static. Returns its index. New boxes are awake.
    uint32_t add_box(glm::vec3 position, glm::vec3 half_extents, float density,
                     glm::quat orientation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f),
                     glm::vec3 velocity = glm::vec3(0.0f),
                     glm::vec3 angular_velocity = glm::vec3(0.0f));

    void step();

    std::span<const Body> bodies() const { return bodies_; }
    std::span<Body> bodies() { return bodies_; }
    Settings& settings() { return settings_; }
    const Settings& settings() const { return settings_; }
    // The contacts of the last step, sorted by pair (those of sleeping
    // bodies included, kept as they were when they fell asleep).
    std::span<const Manifold> manifolds() const { return manifolds_; }
    std::size_t contact_points() const;
    std::size_t awake_count() const;
    // Bodies whose islands took the stiff sub-steps in the last step.
    std::size_t stiff_count() const { return solver_.stiff_bodies(); }
    const StepTimes& times() const { return times_; }
    // Kinetic plus potential energy (height measured from y = 0), joules.
    double energy() const;

private:
    void find_pairs();
    void narrow_phase();
    void continuous();

    Settings settings_;
    std::vector<Body> bodies_;
    std::vector<OrientedBox> boxes_;  // this step's, one per body
    std::vector<Aabb> aabbs_;
    SweepAndPrune sweep_;  // keeps its order from step to step
    std::vector<Pair> pairs_;
    std::vector<Manifold> manifolds_;  // this step's, sorted by pair
    std::vector<Manifold> previous_;   // last step's: the warm start
    std::vector<uint32_t> to_wake_;
    std::vector<Pose> starts_;       // each body's pose before the solver moved it
    std::vector<uint32_t> statics_;  // the static bodies' indices
    Solver solver_;
    Islands islands_;
    StepTimes times_;
};

}  // namespace vkt::physics
