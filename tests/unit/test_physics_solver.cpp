// vkt/domains/physics_solver.hpp (chapter 14), what the sub-stepped soft
// solver must get right: a leaning stack falls, a heavy box rests on a light
// one, and a far heavier one sinks into it as far as page 14d says, with no
// pass that treats the box below as immovable; a staircase that statics says
// stands does, awake, and ten heavy boxes on a light one stand (the stiff
// sub-steps of the islands that need them); a box dropped from about a metre
// bounces however its contact was found; a fast box stops on a thin plate,
// and is not deflected by a box it passes close by; slow spin ends in sleep
// once the box is still; a box woken in a step falls that step. Each test is
// bounded in steps.
#include "vkt/domains/physics_scene.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>

using namespace vkt::physics;
using Catch::Approx;

namespace {

World floor_world(const Settings& settings = {}) {
    World world(settings);
    world.add_box({0, -0.5f, 0}, {20, 0.5f, 20}, 0.0f);  // the floor: top face at y = 0
    return world;
}

// Chapter 14's tower boxes (0.6 x 0.5 x 0.6 m), 20 of them, box k standing
// `lean` further along x than box k - 1, kept awake. By statics the 19 boxes
// above the lowest have their centre of mass beyond its edge, and it tips,
// once the lean passes 0.030 m (10 leans > 0.3 m).
World leaning_staircase(float lean) {
    Settings settings;
    settings.sleep.enabled = false;
    World world = floor_world(settings);
    for (int k = 0; k < 20; ++k)
        world.add_box({lean * float(k), 0.25f + 0.5f * float(k), 0}, {0.3f, 0.25f, 0.3f}, 500.0f);
    return world;
}

}  // namespace

TEST_CASE("a staircase of 20 boxes leaning 5 cm a box falls within 5 s", "[physics]") {
    // Box k stands 5 cm further along x than box k - 1: the centre of mass
    // of the 20 is 0.475 m out over a base 0.3 m wide each way. Nothing can
    // hold it up, and a solver that makes each lower box immovable did.
    World world = floor_world();
    for (int k = 0; k < 20; ++k)
        world.add_box({0.05f * float(k), 0.25f + 0.5f * float(k), 0}, {0.3f, 0.25f, 0.3f}, 500.0f);
    float lowest_top = 10.0f;
    for (int i = 0; i < 120 * 5; ++i) {
        world.step();
        lowest_top = std::min(lowest_top, world.bodies()[20].position.y);
    }
    // The top box started 9.75 m up; fallen, it lies within a metre or so of
    // the floor.
    CHECK(lowest_top < 2.0f);
}

TEST_CASE("a staircase at 80% of its tipping lean stands 30 s awake, and at 110% falls",
          "[physics]") {
    constexpr float kTipping = 0.030f;
    {
        // At the chapter's springs alone it fell within 4 s: each corner's
        // spring, stiff for a fifth of a box's mass, gave under the load
        // above until the load's centre passed the lowest box's edge. Its
        // support chain is 20 bodies tall, so its island takes the stiff
        // sub-steps (page 14d): it settles within 10 s and stays.
        World world = leaning_staircase(0.8f * kTipping);
        for (int i = 0; i < 120 * 10; ++i) world.step();
        const glm::vec3 settled = world.bodies()[20].position;
        float most_off = 0.0f;
        for (int i = 0; i < 120 * 30; ++i) {
            world.step();
            most_off = std::max(most_off, glm::length(world.bodies()[20].position - settled));
        }
        INFO("settled " << (settled.x - 19.0f * 0.8f * kTipping) * 1000.0f << " mm further out");
        CHECK(settled.y > 9.7f);
        CHECK(most_off < 0.005f);
    }
    {
        // Past the tipping lean nothing may hold it: stiffness is no glue.
        World world = leaning_staircase(1.1f * kTipping);
        float lowest_top = 10.0f;
        for (int i = 0; i < 120 * 6; ++i) {
            world.step();
            lowest_top = std::min(lowest_top, world.bodies()[20].position.y);
        }
        CHECK(lowest_top < 2.0f);
    }
}

TEST_CASE("ten boxes 100 times heavier stand 60 s awake on a light one", "[physics]") {
    // Eleven 0.6 m cubes, the lowest at the chapter's 500 kg/m^3, the ten
    // above it 100 times as dense. At the chapter's springs the light cube
    // rocked under the load and the tower twisted about the vertical until
    // it fell, at about 11 s; the mass ratio gives its island the stiff
    // sub-steps.
    Settings settings;
    settings.sleep.enabled = false;
    World world = floor_world(settings);
    world.add_box({0, 0.3f, 0}, glm::vec3(0.3f), 500.0f);
    for (int k = 0; k < 10; ++k)
        world.add_box({0, 0.9f + 0.6f * float(k), 0}, glm::vec3(0.3f), 100.0f * 500.0f);
    const glm::vec3 put = world.bodies()[11].position;
    float most_off = 0.0f, most_twist = 0.0f;
    for (int i = 0; i < 120 * 60; ++i) {
        world.step();
        most_off = std::max(most_off, glm::length(world.bodies()[11].position - put));
        for (const Body& body : world.bodies())
            most_twist = std::max(most_twist, std::abs(body.angular_velocity.y));
    }
    // The top sinks about 2.3 mm into the eleven springs and stays; no cube
    // turns about the vertical faster than 0.02 rad/s, none tilts.
    CHECK(most_off < 0.005f);
    CHECK(most_twist < 0.02f);
    for (const Body& body : world.bodies().subspan(1))
        CHECK(std::abs(rotation(body)[1].y) > std::cos(glm::radians(0.5f)));
}

TEST_CASE("a box 80 times heavier rests on a light one without crushing it", "[physics]") {
    World world = floor_world();
    world.add_box({0, 0.3f, 0}, glm::vec3(0.3f), 500.0f);          // light, below
    world.add_box({0, 0.9f, 0}, glm::vec3(0.3f), 80.0f * 500.0f);  // heavy, on top
    for (int i = 0; i < 120 * 5; ++i) world.step();
    const Body& light = world.bodies()[1];
    const Body& heavy = world.bodies()[2];
    // Each where it started, less the few millimetres the contact springs
    // give under 81 boxes' weight, upright, and at rest.
    CHECK(light.position.y == Approx(0.3f).margin(0.005f));
    CHECK(heavy.position.y == Approx(0.9f).margin(0.005f));
    CHECK(std::abs(rotation(heavy)[1].y) > std::cos(glm::radians(0.5f)));
    CHECK(world.awake_count() == 0);
}

TEST_CASE("a box 1,000 times heavier stands on a light one, each spring giving 0.8-1.4 mm",
          "[physics]") {
    // Page 14d states the contacts' give under a load far beyond their own
    // bodies' mass: the spring's stiffness goes with the light box's mass.
    // At the chapter's 120 Hz a cube 1,000 times as dense sank about 17 mm
    // into the 0.6 m cube under it, which sank as far into the floor; the
    // mass ratio gives their island the stiff sub-steps, springs at 480 Hz,
    // 16 times as stiff, and each gives about 1.1 mm. Kept awake for 60 s,
    // the pair stands, upright, with neither spring giving more (nor, should
    // the solver grow stiffer, less: then the page is wrong) than stated.
    Settings settings;
    settings.sleep.enabled = false;
    World world = floor_world(settings);
    world.add_box({0, 0.3f, 0}, glm::vec3(0.3f), 500.0f);
    world.add_box({0, 0.9f, 0}, glm::vec3(0.3f), 1000.0f * 500.0f);
    float most_off = 0.0f;  // the heavy cube's largest sideways move
    for (int i = 0; i < 120 * 60; ++i) {
        world.step();
        const glm::vec3 p = world.bodies()[2].position;
        most_off = std::max(most_off, std::hypot(p.x, p.z));
    }
    const Body& light = world.bodies()[1];
    const Body& heavy = world.bodies()[2];
    const float light_into_floor = 0.3f - light.position.y;
    const float heavy_into_light = (light.position.y + 0.3f) - (heavy.position.y - 0.3f);
    CHECK(light_into_floor > 0.0008f);
    CHECK(light_into_floor < 0.0014f);
    CHECK(heavy_into_light > 0.0008f);
    CHECK(heavy_into_light < 0.0014f);
    CHECK(most_off < 0.001f);
    CHECK(std::abs(rotation(heavy)[1].y) > std::cos(glm::radians(0.5f)));
    CHECK(std::abs(rotation(light)[1].y) > std::cos(glm::radians(0.5f)));
}

TEST_CASE("a box dropped from about a metre bounces, in 200 drops of 200", "[physics]") {
    // Dropped flat, from 0.8 to 1.2 m, turned at random about the vertical:
    // the step in which the floor is first found leaves a different gap each
    // time, between 0 and the margin. Restitution 0.2: the box must leave the
    // floor at 0.2 times the speed it hit it, within 10%, every time.
    Random random{27u};
    int bounced = 0;
    for (int drop = 0; drop < 200; ++drop) {
        World world = floor_world();
        const float height = random(0.8f, 1.2f);
        const glm::quat turn = glm::angleAxis(random(0.0f, 6.2831853f), glm::vec3(0, 1, 0));
        world.add_box({0, height + 0.25f, 0}, glm::vec3(0.25f), 500.0f, turn);
        float impact = 0.0f, rebound = 0.0f;
        for (int i = 0; i < 120 && rebound == 0.0f; ++i) {
            const float before = world.bodies()[1].velocity.y;
            world.step();
            const float after = world.bodies()[1].velocity.y;
            if (after > before + 0.5f) impact = -before, rebound = after;  // the step it hit
        }
        INFO("drop " << drop << " from " << height << " m: hit at " << impact << " m/s, left at "
                     << rebound << " m/s");
        const bool good = impact > 3.0f && std::abs(rebound / impact - 0.2f) <= 0.02f;
        if (!good) CHECK(good);  // says which drop failed
        bounced += good ? 1 : 0;
    }
    CHECK(bounced == 200);
}

TEST_CASE("a box dropped at any orientation bounces at every point it lands on", "[physics]") {
    // From 0.8 to 1.2 m, turned at random about any axis: most land on a
    // corner, some on an edge, a few on three corners or a face. Whatever
    // it lands on, each point that touched leaves at e times the speed it
    // came in at (the point's normal velocity, before the step and after,
    // at the place the step found it), within 10%.
    Random random{123u};
    int bounced = 0;
    for (int drop = 0; drop < 200; ++drop) {
        World world = floor_world();
        const float height = random(0.8f, 1.2f);
        // Half a diagonal (0.43 m) clears the floor whatever the turn.
        world.add_box({0, height + 0.45f, 0}, glm::vec3(0.25f), 500.0f, random_orientation(random));
        float worst = 0.0f;  // the largest error of e found, as a share of e
        int points = 0;
        for (int i = 0; i < 120 && points == 0; ++i) {
            const Body before = world.bodies()[1];
            world.step();
            const Body& after = world.bodies()[1];
            for (const Manifold& m : world.manifolds())
                for (uint32_t k = 0; k < m.count; ++k) {
                    const glm::vec3 r = m.points[k].position - before.position;
                    const float in = (before.velocity + glm::cross(before.angular_velocity, r)).y;
                    if (m.points[k].normal_impulse <= 0.0f || in > -1.0f) continue;
                    const float out = (after.velocity + glm::cross(after.angular_velocity, r)).y;
                    worst = std::max(worst, std::abs(out / -in - 0.2f) / 0.2f);
                    ++points;
                }
        }
        INFO("drop " << drop << " from " << height << " m: " << points
                     << " points, the worst off by " << worst * 100.0f << "%");
        const bool good = points > 0 && worst <= 0.1f;
        if (!good) CHECK(good);  // says which drop failed
        bounced += good ? 1 : 0;
    }
    CHECK(bounced == 200);
}

TEST_CASE("a fast box stops on a thin plate instead of passing through", "[physics]") {
    // A 0.3 m box falls onto a static plate 10 or 2 cm thick at 30, 50 and
    // 100 m/s: 0.25 to 0.83 m a step, more than the plate and the box
    // together from 50 m/s on. Speculative contacts reach only 2 cm; the
    // time-of-impact pass stops the box where it first comes within the
    // margin of the plate, and the next step's contact stops it there.
    for (float thickness : {0.1f, 0.02f})
        for (float speed : {30.0f, 50.0f, 100.0f}) {
            INFO(speed << " m/s onto " << thickness << " m");
            Settings settings;
            settings.solver.restitution = 0.0f;  // it stops where it hits
            World world = floor_world(settings);
            const float top = 1.0f + 0.5f * thickness;
            world.add_box({0, 1, 0}, {2, 0.5f * thickness, 2}, 0.0f);  // the plate
            world.add_box({0, 3, 0}, glm::vec3(0.15f), 500.0f, glm::quat(1, 0, 0, 0),
                          glm::vec3(0, -speed, 0));
            float lowest = 3.0f;
            for (int i = 0; i < 120; ++i) {
                world.step();
                lowest = std::min(lowest, world.bodies()[2].position.y);
            }
            CHECK(lowest > top + 0.15f - 0.01f);
            CHECK(world.bodies()[2].position.y == Approx(top + 0.15f).margin(0.005f));
        }
}

TEST_CASE("a fast box passing a box diagonally is not deflected, in 72 near misses", "[physics]") {
    // No gravity. A 0.3 m box flies at 30 m/s along a diagonal past a corner
    // of a static 1 m box, its own corner passing the static one's at 3 to
    // 11 cm: the boxes never touch, so the box must leave as it came. Four
    // corners, two ways past each, nine clearances: 72 paths.
    Settings settings;
    settings.sleep.enabled = false;
    settings.gravity = glm::vec3(0.0f);
    int missed = 0;
    for (int corner = 0; corner < 4; ++corner)
        for (int way = 0; way < 2; ++way)
            for (int c = 0; c < 9; ++c) {
                const float clearance = 0.03f + 0.01f * float(c);
                const glm::vec2 out(corner & 1 ? 1.0f : -1.0f, corner & 2 ? 1.0f : -1.0f);
                // Along the corner's diagonal's perpendicular, one way or the other.
                const glm::vec2 along = (way ? 1.0f : -1.0f) * glm::vec2(-out.y, out.x);
                // Closest approach: the two boxes' corners `clearance` apart
                // along `out` (diagonal, so each axis gets clearance / sqrt 2).
                const glm::vec2 closest = out * (0.65f + clearance / std::sqrt(2.0f));
                const glm::vec2 start = closest - 1.0f * glm::normalize(along) * 1.0f;
                const glm::vec3 velocity =
                    30.0f * glm::vec3(glm::normalize(along).x, 0, glm::normalize(along).y);
                World world(settings);
                world.add_box({0, 0, 0}, glm::vec3(0.5f), 0.0f);
                world.add_box({start.x, 0, start.y}, glm::vec3(0.15f), 500.0f,
                              glm::quat(1, 0, 0, 0), velocity);
                for (int i = 0; i < 30; ++i) world.step();  // 0.25 s: 7.5 m, long past it
                const Body& box = world.bodies()[1];
                const float change = glm::length(box.velocity - velocity);
                const float spin = glm::length(box.angular_velocity);
                INFO("corner " << corner << ", way " << way << ", clearance " << clearance
                               << " m: velocity changed by " << change << " m/s, spin " << spin
                               << " rad/s");
                const bool good = change < 0.01f && spin < 0.01f;
                if (!good) CHECK(good);
                missed += good ? 1 : 0;
            }
    CHECK(missed == 72);
}

TEST_CASE("a slow spin ends: the box falls asleep once its corners stop", "[physics]") {
    // A box of 0.9 x 0.9 x 0.9 m turning at 0.06 rad/s in free space, with no
    // gravity: nothing stops it but the angular damping. Its corners move at
    // 0.047 m/s, under the 0.05 m/s a body must stay below to rest, but a
    // body also rests only while it stays within 2 mm of its anchor: the
    // corners must first slow to about 2 mm in 0.5 s (0.0051 rad/s), which
    // the damping's e^(-0.2 t) reaches after ln(0.06 / 0.0051) / 0.2 = 12.3 s.
    // Judged by speed alone, it would sleep at once, still turning.
    Settings settings;
    settings.gravity = glm::vec3(0.0f);
    World world(settings);
    world.add_box({0, 0, 0}, glm::vec3(0.45f), 500.0f, glm::quat(1, 0, 0, 0), glm::vec3(0.0f),
                  glm::vec3(0.0f, 0.06f, 0.0f));
    int steps = 0;
    for (; steps < 120 * 20 && world.awake_count() > 0; ++steps) world.step();
    INFO("asleep after " << steps << " steps");
    CHECK(world.awake_count() == 0);
    CHECK(steps > 120 * 11);  // not while it still turns
    // The damping alone: 0.2 per second takes 10 rad/s to 10 e^-2 in 10 s.
    Settings free_settings = settings;
    free_settings.sleep.enabled = false;
    World spinning(free_settings);
    spinning.add_box({0, 0, 0}, glm::vec3(0.45f), 500.0f, glm::quat(1, 0, 0, 0), glm::vec3(0.0f),
                     glm::vec3(0.0f, 10.0f, 0.0f));
    for (int i = 0; i < 1200; ++i) spinning.step();
    CHECK(glm::length(spinning.bodies()[0].angular_velocity) ==
          Approx(10.0 * std::exp(-2.0)).epsilon(0.01));
}

TEST_CASE("5,000 boxes are all asleep within 15 s", "[physics]") {
    World world;
    add_falling_boxes(world, 5000);
    int steps = 0;
    for (; steps < 120 * 15 && world.awake_count() > 0; ++steps) world.step();
    INFO("awake after " << steps << " steps: " << world.awake_count());
    CHECK(world.awake_count() == 0);
}

TEST_CASE("a box woken during a step falls in that step", "[physics]") {
    // A box asleep in mid-air (put to sleep by hand, its own island), and a
    // box sliding into its side. The narrow phase wakes the sleeper; gravity
    // must then act on it in the same step, as on every moving body.
    World world = floor_world();
    const uint32_t sleeper = world.add_box({0, 5, 0}, glm::vec3(0.25f), 500.0f);
    world.add_box({-0.501f, 5, 0}, glm::vec3(0.25f), 500.0f, glm::quat(1, 0, 0, 0),
                  glm::vec3(0.5f, 0, 0));
    Body& body = world.bodies()[sleeper];
    body.awake = 0;
    body.island = sleeper;
    world.step();
    REQUIRE(world.bodies()[sleeper].awake == 1);
    const float dt = world.settings().time_step;
    CHECK(world.bodies()[sleeper].velocity.y == Approx(-9.81f * dt).epsilon(0.01));
}
