// vkt/domains/physics.hpp (chapter 14), the solver's promises: a pyramid and
// a tall tower stand still, a box dropped on a corner ends on a face, a box on
// a ramp stays or slides as Coulomb's law says, sleeping islands wake when
// touched, and an island sleeps only once its bodies have stopped moving.
#include "vkt/domains/physics_scene.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace vkt::physics;
using Catch::Approx;

namespace {

// The angle in degrees between two orientations.
float angle_between(glm::quat a, glm::quat b) {
    const float c = std::min(std::abs(glm::dot(a, b)), 1.0f);
    return glm::degrees(2.0f * std::acos(c));
}

struct Stillness {
    float most_moved = 0.0f;   // metres, the largest distance any box got from its start
    float most_turned = 0.0f;  // degrees
};

// Steps the world for `seconds`, watching every box after every step.
Stillness watch(World& world, float seconds) {
    const std::vector<Body> start(world.bodies().begin(), world.bodies().end());
    Stillness s;
    const int steps = int(std::lround(seconds / world.settings().time_step));
    for (int i = 0; i < steps; ++i) {
        world.step();
        for (std::size_t k = 0; k < start.size(); ++k) {
            const Body& now = world.bodies()[k];
            s.most_moved = std::max(s.most_moved, glm::length(now.position - start[k].position));
            s.most_turned =
                std::max(s.most_turned, angle_between(now.orientation, start[k].orientation));
        }
    }
    return s;
}

World floor_world(bool sleeping) {
    Settings settings;
    settings.sleep.enabled = sleeping;
    World world(settings);
    world.add_box({0, -0.5f, 0}, {20, 0.5f, 20}, 0.0f);  // the floor: top face at y = 0
    return world;
}

// Chapter 14's tower's boxes (0.6 x 0.5 x 0.6 m), each `lean` further along
// x than the one below. By statics it tips when lean > 0.03 m: the load on
// box k - 1, the 20 - k boxes above it, is centred lean (21 - k) / 2 beyond
// its centre, which must stay within its half width of 0.3 m (worst: k = 1).
constexpr int kSteps = 20;

void add_staircase(World& world, float lean) {
    for (int k = 0; k < kSteps; ++k)
        world.add_box({lean * float(k), 0.25f + 0.5f * float(k), 0}, {0.3f, 0.25f, 0.3f}, 500.0f);
}

// The largest distance any corner of `now` is from the same corner of `then`.
float corner_moved(const Body& now, const Body& then) {
    float most = 0.0f;
    const glm::mat3 r1 = rotation(now), r0 = rotation(then);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 sign(c & 1 ? 1.0f : -1.0f, c & 2 ? 1.0f : -1.0f, c & 4 ? 1.0f : -1.0f);
        const glm::vec3 local = sign * now.half_extents;
        most = std::max(most, glm::length(now.position + r1 * local - then.position - r0 * local));
    }
    return most;
}

}  // namespace

TEST_CASE("a 10-level pyramid of 55 boxes stands still for 30 s", "[physics]") {
    for (bool sleeping : {true, false}) {
        INFO((sleeping ? "with" : "without") << " sleeping");
        World world = floor_world(sleeping);
        // Chapter 14's pyramid: cubes of 0.6 m, 2 cm apart in a row, each row
        // on the one below, placed exactly touching.
        add_pyramid(world, {0, 0, 0}, 10, 0.3f, 0.02f);
        REQUIRE(world.bodies().size() == 56);
        // Asleep, nothing moves (and stepping costs nothing); awake, the
        // solver alone holds it, step after step, for the whole 30 s too
        // (3,600 steps of 55 boxes: under a second in a release build).
        const Stillness s = watch(world, 30.0f);
        // Tolerances: 1 mm, and 0.5 degrees ("none tips": tipping is tens of
        // degrees).
        CHECK(s.most_moved < 0.001f);
        CHECK(s.most_turned < 0.5f);
        if (sleeping) CHECK(world.awake_count() == 0);
    }
}

TEST_CASE("a tower of 20 boxes stands still for 30 s", "[physics]") {
    for (bool sleeping : {true, false}) {
        INFO((sleeping ? "with" : "without") << " sleeping");
        World world = floor_world(sleeping);
        // Chapter 14's tower: 20 boxes of 0.6 x 0.5 x 0.6 m, 10 m high,
        // 17 times as tall as it is wide. Nothing holds it but the contacts
        // (no pass that treats the box below as immovable).
        add_tower(world, {0, 0, 0}, 20, glm::vec3(0.3f, 0.25f, 0.3f));
        // The contact springs take the weight in the first second: the top
        // sinks about 0.5 mm (19 soft contacts, each under the boxes above
        // it; 8 mm on the chapter's springs, but a chain 20 bodies tall
        // gives the island the stiff sub-steps, springs 16 times as stiff).
        for (int i = 0; i < 120; ++i) world.step();
        CHECK(world.bodies()[20].position.y == Approx(9.75f).margin(0.01f));
        // Then it stands: for 30 s more no box moves a millimetre, asleep or
        // awake, and none turns half a degree. (Awake, the top box swayed
        // 1-4 mm while every pass solved each contact's points in the same
        // order; the solver's passes now start at each point in turn.)
        const Stillness s = watch(world, 30.0f);
        CHECK(s.most_moved < 0.001f);
        CHECK(s.most_turned < 0.5f);
    }
}

TEST_CASE("a box dropped on a corner ends resting flat on a face", "[physics]") {
    World world = floor_world(true);
    // A cube with its long diagonal (1, 1, 1) turned to point straight down,
    // then tipped 3 degrees so that it does not balance on the corner forever.
    const glm::vec3 diagonal = glm::normalize(glm::vec3(1, 1, 1));
    const glm::vec3 down(0, -1, 0);
    const glm::quat corner_down = glm::angleAxis(std::acos(glm::dot(diagonal, down)),
                                                 glm::normalize(glm::cross(diagonal, down)));
    const glm::quat q = glm::angleAxis(glm::radians(3.0f), glm::vec3(0, 0, 1)) * corner_down;
    // Its corner 1 m above the floor (the corner is sqrt(3) / 2 from the centre).
    world.add_box({0, 1.0f + 0.5f * std::sqrt(3.0f), 0}, glm::vec3(0.5f), 500.0f, q);
    for (int i = 0; i < 120 * 6; ++i) world.step();  // 6 s
    const Body& cube = world.bodies()[1];
    // At rest, asleep, its centre half a metre up (less a few tenths of a
    // millimetre in the floor), one of its axes vertical within a degree.
    CHECK(cube.awake == 0);
    CHECK(cube.position.y == Approx(0.5f).margin(0.002f));
    const glm::mat3 r = rotation(cube);
    const float up = std::max({std::abs(r[0].y), std::abs(r[1].y), std::abs(r[2].y)});
    CHECK(up > std::cos(glm::radians(1.0f)));
}

namespace {

// A box of half size 0.25 resting on a 20 degree ramp, turned with it, with
// friction `mu`; returns how far it has moved down the slope after `seconds`.
float slide_on_ramp(float mu, float seconds, float degrees = 20.0f) {
    Settings settings;
    settings.solver.friction = mu;
    World world(settings);
    const float angle = glm::radians(degrees);
    const glm::quat turn = glm::angleAxis(angle, glm::vec3(0, 0, 1));
    const glm::vec3 along(std::cos(angle), std::sin(angle), 0.0f);  // up the slope
    const glm::vec3 up(-std::sin(angle), std::cos(angle), 0.0f);    // the ramp's normal
    world.add_box({0, 0, 0}, {6, 0.25f, 2}, 0.0f, turn);            // the ramp
    const glm::vec3 start = 4.5f * along + 0.5f * up;  // on its top face, near the top end
    world.add_box(start, glm::vec3(0.25f), 500.0f, turn);
    for (int i = 0; i < int(std::lround(seconds * 120.0f)); ++i) world.step();
    return glm::dot(start - world.bodies()[1].position, along);
}

}  // namespace

TEST_CASE("a box on a 20 degree ramp stays with friction 0.5 and slides with 0.2", "[physics]") {
    // Coulomb: it slides when the pull along the slope, m g sin(a), beats the
    // most friction can hold, mu m g cos(a): when tan(a) > mu, a > atan(mu).
    // atan(0.5) = 26.6 degrees: 20 degrees holds. atan(0.2) = 11.3: it slides.
    CHECK(std::abs(slide_on_ramp(0.5f, 3.0f)) < 0.001f);
    // Sliding, it accelerates at g (sin(a) - mu cos(a)) = 9.81 (0.3420 -
    // 0.2 * 0.9397) = 1.5115 m/s^2: 3.02 m in 2 s. Tolerance 2%.
    const float slid = slide_on_ramp(0.2f, 2.0f);
    CHECK(slid == Approx(0.5 * 1.5115 * 2.0 * 2.0).epsilon(0.02));
    // The critical angle is atan(mu): tan(20 degrees) = 0.364; just above it
    // holds, just below it slides.
    CHECK(std::abs(slide_on_ramp(0.38f, 2.0f)) < 0.001f);
    CHECK(slide_on_ramp(0.35f, 2.0f) > 0.05f);
}

TEST_CASE("resting islands fall asleep and wake when touched", "[physics]") {
    World world = floor_world(true);
    add_tower(world, {0, 0, 0}, 3, glm::vec3(0.5f));
    world.add_box({5, 0.5f, 0}, glm::vec3(0.5f), 500.0f);  // alone, far away
    for (int i = 0; i < 120; ++i) world.step();            // 1 s: longer than the 0.5 s it takes
    REQUIRE(world.awake_count() == 0);
    const Body before = world.bodies()[3];
    // Resting means zero velocity, and the contacts are kept as they were.
    CHECK(before.velocity == glm::vec3(0.0f));
    CHECK(world.manifolds().size() == 4);
    // A box dropped on the top of the tower wakes the tower's island (all three
    // boxes, through their contacts), but not the box far away.
    world.add_box({0, 3.6f, 0}, glm::vec3(0.5f), 500.0f);
    bool woke = false;
    for (int i = 0; i < 60 && !woke; ++i) {
        world.step();
        woke = world.bodies()[1].awake && world.bodies()[2].awake && world.bodies()[3].awake;
        CHECK(world.bodies()[4].awake == 0);
    }
    CHECK(woke);
    // It lands, and all of them sleep again, the tower where it stood.
    for (int i = 0; i < 240; ++i) world.step();
    CHECK(world.awake_count() == 0);
    CHECK(world.bodies()[5].position.y == Approx(3.5f).margin(0.002f));
    CHECK(glm::length(world.bodies()[3].position - before.position) < 0.001f);
}

TEST_CASE("an island sleeps only when every body stayed put for the last 0.5 s", "[physics]") {
    // Scenes that rest, sway, or fall: staircases at 17% to 93% of their
    // tipping lean, and 300 boxes falling into heaps. Whenever a body falls
    // asleep, each of its corners must be within 6 mm of where it was 60
    // steps (0.5 s) before (three times the 2 mm a resting body may stray
    // from its anchor: physics_sleep.hpp): an island asleep mid-swing fails.
    struct Scene {
        float lean;  // 0: the falling boxes
        int seconds;
    };
    for (const Scene scene : {Scene{0.005f, 12}, Scene{0.0175f, 12}, Scene{0.024f, 12},
                              Scene{0.028f, 12}, Scene{0.0f, 10}}) {
        INFO("lean " << scene.lean << " m");
        World world = floor_world(true);
        if (scene.lean > 0.0f)
            add_staircase(world, scene.lean);
        else
            add_falling_boxes(world, 300);
        constexpr int kWindow = 60;
        std::vector<std::vector<Body>> history;  // the last kWindow steps, oldest first
        float worst = 0.0f;
        int slept = 0;
        for (int i = 0; i < 120 * scene.seconds; ++i) {
            history.emplace_back(world.bodies().begin(), world.bodies().end());
            if (history.size() > kWindow + 1) history.erase(history.begin());
            world.step();
            if (history.size() <= kWindow) continue;
            for (std::size_t k = 0; k < world.bodies().size(); ++k) {
                const Body& now = world.bodies()[k];
                if (now.is_static() || now.awake || !history.back()[k].awake) continue;
                ++slept;  // fell asleep this step
                worst = std::max(worst, corner_moved(now, history[1][k]));
            }
        }
        INFO(slept << " bodies fell asleep; the furthest had moved " << worst * 1000.0f
                   << " mm in its last 0.5 s");
        CHECK(worst < 0.006f);
        if (scene.lean == 0.0f) CHECK(world.awake_count() == 0);  // the heaps do sleep
    }
}
