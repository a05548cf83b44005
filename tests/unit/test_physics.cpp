// vkt/domains/physics.hpp (chapter 14): overlap and penetration on hand-worked pairs,
// resting and stacking, energy in a closed box, broad phase against brute
// force, and bit-equal repeat runs.
#include "vkt/domains/physics.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <cmath>
#include <cstring>

using namespace vkt::physics;
using Catch::Approx;

namespace {

Body box(glm::vec3 position, glm::vec3 half, float inverse_mass = 1.0f) {
    return Body{position, half, glm::vec3(0.0f), inverse_mass};
}

// The largest distance any body moved between two snapshots.
float largest_move(std::span<const Body> before, std::span<const Body> after) {
    float most = 0.0f;
    for (std::size_t i = 0; i < before.size(); ++i)
        most = std::max(most, glm::length(after[i].position - before[i].position));
    return most;
}

// xorshift32, as in physics.cpp: the same scenes everywhere.
struct Random {
    uint32_t state;
    float operator()(float low, float high) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        return low + (high - low) * float(state >> 8) * (1.0f / 16777216.0f);
    }
};

}  // namespace

TEST_CASE("overlap and the axis of least penetration, worked by hand", "[physics]") {
    const Body a = box({0, 0, 0}, {1, 1, 1});
    // b 1.5 to the right, 0.5 up: overlaps 2 - 1.5 = 0.5 (x), 2 - 0.5 = 1.5
    // (y), 2 (z): least along x, pointing from a to b: +x, depth 0.5.
    auto p = penetration(a, box({1.5f, 0.5f, 0}, {1, 1, 1}));
    REQUIRE(p);
    CHECK(p->axis == 0);
    CHECK(p->sign == 1.0f);
    CHECK(p->depth == 0.5f);
    CHECK(p->normal() == glm::vec3(1, 0, 0));
    // b below a: overlaps 2 (x), 2 - 1.8 = 0.2 (y), 2 - 0.3 = 1.7 (z): -y, 0.2.
    p = penetration(a, box({0, -1.8f, 0.3f}, {1, 1, 1}));
    REQUIRE(p);
    CHECK(p->axis == 1);
    CHECK(p->sign == -1.0f);
    CHECK(p->depth == Approx(0.2f));
    // Different sizes: a (2, 0.5, 1), b (0.5, 0.5, 0.5) at (0, 0.9, -1.2):
    // overlaps 2.5 (x), 1.0 - 0.9 = 0.1 (y), 1.5 - 1.2 = 0.3 (z): +y, 0.1.
    p = penetration(box({0, 0, 0}, {2, 0.5f, 1}), box({0, 0.9f, -1.2f}, {0.5f, 0.5f, 0.5f}));
    REQUIRE(p);
    CHECK(p->axis == 1);
    CHECK(p->sign == 1.0f);
    CHECK(p->depth == Approx(0.1f));
    // Along z the other way: b at (0.5, 0, -1.75): overlaps 1.5, 2, 0.25: -z.
    p = penetration(a, box({0.5f, 0, -1.75f}, {1, 1, 1}));
    REQUIRE(p);
    CHECK(p->axis == 2);
    CHECK(p->sign == -1.0f);
    CHECK(p->depth == 0.25f);
    // A tie (x and y both 1) goes to the lower axis, x.
    p = penetration(a, box({1, 1, 0}, {1, 1, 1}));
    REQUIRE(p);
    CHECK(p->axis == 0);
    // Same centre: every depth is 1.5, so x, and the normal points along +x.
    p = penetration(a, box({0, 0, 0}, {0.5f, 0.5f, 0.5f}));
    REQUIRE(p);
    CHECK(p->axis == 0);
    CHECK(p->sign == 1.0f);
    CHECK(p->depth == 1.5f);
}

TEST_CASE("boxes that touch or are apart do not overlap", "[physics]") {
    const Body a = box({0, 0, 0}, {1, 1, 1});
    CHECK_FALSE(overlaps(a, box({2, 0, 0}, {1, 1, 1})));  // faces touch: depth 0
    CHECK_FALSE(penetration(a, box({2, 0, 0}, {1, 1, 1})));
    CHECK_FALSE(overlaps(a, box({0, 0, -2.5f}, {1, 1, 1})));  // apart along z only
    CHECK_FALSE(penetration(a, box({1.5f, 1.5f, 2.1f}, {1, 1, 1})));
    CHECK(overlaps(a, box({1.99f, 1.99f, 1.99f}, {1, 1, 1})));  // a corner inside
    // The pair finders and the step agree: apart boxes give no contact.
    const Body pair[] = {a, box({0, 3, 0}, {1, 1, 1})};
    CHECK(find_pairs_brute_force(pair).empty());
}

TEST_CASE("a box resting on the floor stays at rest for 10,000 steps", "[physics]") {
    World world;
    world.add_box({0, -0.5f, 0}, {10, 0.5f, 10}, 0.0f);  // floor, top at y = 0
    // Resting: 2 mm into the floor, within the 5 mm slop.
    world.add_box({0.3f, 0.498f, -0.2f}, {0.5f, 0.5f, 0.5f}, 500.0f);
    const Body start = world.bodies()[1];
    for (int i = 0; i < 10000; ++i) world.step();
    const Body end = world.bodies()[1];
    // Epsilon: 1e-5 m (0.01 mm), over 83 simulated seconds.
    CHECK(glm::length(end.position - start.position) < 1e-5f);
    CHECK(glm::length(end.velocity) < 1e-4f);
}

TEST_CASE("a stack of 10 boxes settles and stays, in order", "[physics]") {
    World world;
    world.add_box({0, -0.5f, 0}, {10, 0.5f, 10}, 0.0f);
    float y = 0.0f;
    for (int i = 0; i < 10; ++i) {
        // Different sizes and masses; each just above the one below.
        const glm::vec3 half(0.5f - 0.02f * float(i), 0.25f + 0.02f * float(i), 0.45f);
        y += half.y + 0.001f;
        world.add_box({0.01f * float(i % 3), y, 0}, half, 300.0f + 50.0f * float(i));
        y += half.y;
    }
    for (int i = 0; i < 600; ++i) world.step();  // 5 s to settle
    const std::vector<Body> settled(world.bodies().begin(), world.bodies().end());
    for (int i = 0; i < 1000; ++i) world.step();
    const auto now = world.bodies();
    // Epsilon: 1e-4 m (0.1 mm) over 1,000 steps (8.3 s).
    CHECK(largest_move(settled, now) < 1e-4f);
    for (int i = 1; i <= 10; ++i) {
        const Body& below = now[std::size_t(i - 1)];
        const Body& above = now[std::size_t(i)];
        // Kept in order: each box sits on the one below, into it by no more
        // than a little over the slop, and has not slid sideways.
        const float gap =
            (above.position.y - above.half_extents.y) - (below.position.y + below.half_extents.y);
        CHECK(gap < 0.0f);
        CHECK(gap > -0.01f);
        CHECK(std::abs(above.position.x - settled[std::size_t(i)].position.x) < 1e-4f);
    }
}

// The closed box: six static walls around [-4, 4]^3, no gravity, 216 boxes
// of random sizes and masses flying about at up to 6 m/s. Returns the largest
// growth of kinetic energy in one step, as a share of the starting energy.
static double worst_energy_growth(float restitution, float friction, bool warm_start, double& end) {
    Settings settings;
    settings.gravity = glm::vec3(0.0f);
    settings.restitution = restitution;
    settings.friction = friction;
    settings.warm_start = warm_start;
    World world(settings);
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 position(0.0f), half(5.0f);
            position[axis] = side * 4.5f;
            half[axis] = 0.5f;
            world.add_box(position, half, 0.0f);
        }
    Random random{7u};
    for (int i = 0; i < 216; ++i) {
        const glm::vec3 at(float(i % 6), float(i / 6 % 6), float(i / 36));
        const glm::vec3 half(random(0.15f, 0.6f), random(0.15f, 0.6f), random(0.15f, 0.6f));
        const glm::vec3 velocity(random(-6, 6), random(-6, 6), random(-6, 6));
        world.add_box((at - 2.5f) * 1.3f, half, random(100, 1000), velocity);
    }
    double energy = world.kinetic_energy();
    const double start = energy;
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {  // checked after every step
        world.step();
        const double now = world.kinetic_energy();
        worst = std::max(worst, (now - energy) / start);
        energy = now;
    }
    end = energy / start;
    return worst;
}

TEST_CASE("kinetic energy never grows in a closed box without gravity", "[physics]") {
    for (float restitution : {0.0f, 0.5f, 1.0f}) {
        for (float friction : {0.0f, 0.5f}) {
            INFO("restitution " << restitution << ", friction " << friction);
            // The solver itself: each impulse only takes energy out (or, at
            // restitution 1, keeps it). Tolerance: 1e-9 of the starting
            // energy per step, float rounding (measured: below 1e-10).
            double end = 0.0;
            CHECK(worst_energy_growth(restitution, friction, false, end) <= 1e-9);
            if (restitution < 1.0f) CHECK(end < 0.5);
            // Warm started (the default): last step's impulses are a guess,
            // and a guess left unconverged after 10 passes can add a little.
            // Tolerance: 1e-3 of the starting energy per step (measured:
            // at most 4.6e-4, at restitution 0 and friction 0.5).
            CHECK(worst_energy_growth(restitution, friction, true, end) <= 1e-3);
        }
    }
}

TEST_CASE("sort-and-sweep finds exactly the pairs brute force finds", "[physics]") {
    std::vector<uint32_t> order;
    for (uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
        for (float side : {4.0f, 12.0f, 40.0f}) {  // dense, medium, sparse
            for (uint32_t count : {10u, 200u, 1500u}) {
                Random random{seed * 7919u + count};
                std::vector<Body> bodies;
                for (uint32_t i = 0; i < count; ++i) {
                    const glm::vec3 at(random(-side, side), random(-side, side),
                                       random(-side, side));
                    const glm::vec3 half(random(0.1f, 1.0f), random(0.1f, 1.0f),
                                         random(0.1f, 1.0f));
                    // Every fifth static; every seventh sharing the last
                    // one's lowest x exactly (ties in the sort).
                    glm::vec3 p = at;
                    if (i % 7 == 6)
                        p.x = bodies.back().position.x - bodies.back().half_extents.x + half.x;
                    bodies.push_back(box(p, half, i % 5 == 0 ? 0.0f : 1.0f));
                }
                const auto brute = find_pairs_brute_force(bodies);
                const auto sweep = find_pairs_sweep(bodies, order);
                INFO("seed " << seed << ", side " << side << ", " << count << " boxes, "
                             << brute.size() << " pairs");
                CHECK(sweep == brute);
                for (const Pair& pair : brute)
                    CHECK_FALSE(
                        (bodies[pair.a].inverse_mass == 0 && bodies[pair.b].inverse_mass == 0));
            }
        }
    }
}

TEST_CASE("the same inputs give bit-equal results", "[physics]") {
    auto run = [](BroadPhase broad_phase) {
        Settings settings;
        settings.broad_phase = broad_phase;
        World world(settings);
        add_falling_boxes(world, 400);
        for (int i = 0; i < 300; ++i) world.step();
        return std::vector<Body>(world.bodies().begin(), world.bodies().end());
    };
    const auto first = run(BroadPhase::sweep_and_prune);
    const auto second = run(BroadPhase::sweep_and_prune);
    REQUIRE(first.size() == 401);
    CHECK(std::memcmp(first.data(), second.data(), first.size() * sizeof(Body)) == 0);
    // The pairs come out in the same order from both broad phases, so the
    // whole simulation is the same, bit for bit, whichever found them.
    const auto brute = run(BroadPhase::brute_force);
    CHECK(std::memcmp(first.data(), brute.data(), first.size() * sizeof(Body)) == 0);
    // And it moved: the boxes fell.
    CHECK(first[400].position.y < 1.0f + 9 * 1.3f);
}
