// vkt/domains/physics_*.hpp (chapter 14), the geometry: box inertia and its
// world-space form, the AABB of a turned box, the separating axis test on
// hand-worked pairs, contact manifolds and their feature ids, and the two
// broad phases against each other.
#include "vkt/domains/physics_scene.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>

using namespace vkt::physics;
using Catch::Approx;

namespace {

OrientedBox box(glm::vec3 centre, glm::vec3 half, glm::quat q = glm::quat(1, 0, 0, 0)) {
    return {centre, glm::mat3_cast(q), half};
}

glm::quat about(float degrees, glm::vec3 axis) {
    return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

bool has_point_near(const Manifold& m, glm::vec3 p, float tolerance = 1e-4f) {
    for (uint32_t i = 0; i < m.count; ++i)
        if (glm::length(m.points[i].position - p) < tolerance) return true;
    return false;
}

}  // namespace

TEST_CASE("a box's inertia, worked by hand", "[physics]") {
    // A cube of 12 kg, half size 1: I = m (b^2 + c^2) / 3 = 12 * 2 / 3 = 8.
    CHECK(box_inverse_inertia(glm::vec3(1.0f), 12.0f) == glm::vec3(1.0f / 8.0f));
    // 6 kg, half extents (1, 2, 3): I_x = 6 (4 + 9) / 3 = 26, I_y = 6 (1 + 9) / 3
    // = 20, I_z = 6 (1 + 4) / 3 = 10: the long axis (z) is the easiest to spin about.
    const glm::vec3 i = box_inverse_inertia({1, 2, 3}, 6.0f);
    CHECK(i.x == Approx(1.0 / 26));
    CHECK(i.y == Approx(1.0 / 20));
    CHECK(i.z == Approx(1.0 / 10));
    CHECK(box_inverse_inertia({1, 2, 3}, 0.0f) == glm::vec3(0.0f));  // static
}

TEST_CASE("the world inverse inertia is R I^-1 R^T", "[physics]") {
    const glm::vec3 inverse(1.0f / 26, 1.0f / 20, 1.0f / 10);
    // Unturned: the diagonal itself.
    glm::mat3 w = world_inverse_inertia(glm::mat3(1.0f), inverse);
    CHECK(w[0][0] == Approx(inverse.x));
    CHECK(w[1][1] == Approx(inverse.y));
    CHECK(w[2][2] == Approx(inverse.z));
    // Turned 90 degrees about z: the body's x axis now lies along world y, so
    // spinning about world y meets the body's x moment, and about world x the
    // body's y moment.
    w = world_inverse_inertia(glm::mat3_cast(about(90, {0, 0, 1})), inverse);
    CHECK(w[0][0] == Approx(inverse.y));
    CHECK(w[1][1] == Approx(inverse.x));
    CHECK(w[2][2] == Approx(inverse.z));
    CHECK(std::abs(w[1][0]) < 1e-6f);
    // Turned 45 degrees about z: a torque about world x spins the box about
    // both x and y (off-diagonal terms), with (i_x + i_y) / 2 on the diagonal.
    w = world_inverse_inertia(glm::mat3_cast(about(45, {0, 0, 1})), inverse);
    CHECK(w[0][0] == Approx(0.5 * (inverse.x + inverse.y)));
    CHECK(std::abs(w[0][1]) == Approx(0.5 * std::abs(inverse.x - inverse.y)));
    CHECK(w[0][1] == Approx(w[1][0]));  // symmetric
}

TEST_CASE("the AABB of a turned box", "[physics]") {
    // A 2 x 1 x 1 box (half 1, 0.5, 0.5) turned 90 degrees about z: 1 x 2 x 1.
    Aabb a = world_aabb({1, 2, 3}, glm::mat3_cast(about(90, {0, 0, 1})), {1, 0.5f, 0.5f}, 0.0f);
    CHECK(a.low.x == Approx(0.5f));
    CHECK(a.high.y == Approx(3.0f));
    CHECK(a.high.z == Approx(3.5f));
    // A unit cube (half 0.5) turned 45 degrees about y reaches 0.5 sqrt(2)
    // along x and z; the margin grows it on every side.
    a = world_aabb({0, 0, 0}, glm::mat3_cast(about(45, {0, 1, 0})), glm::vec3(0.5f), 0.01f);
    CHECK(a.high.x == Approx(0.5f * std::sqrt(2.0f) + 0.01f));
    CHECK(a.high.y == Approx(0.51f));
}

TEST_CASE("the separating axis test, worked by hand", "[physics]") {
    const OrientedBox a = box({0, 0, 0}, glm::vec3(1.0f));
    // Axis-aligned, b above and to the side: overlaps 2 - 1.5 = 0.5 along x,
    // 2 - 1.8 = 0.2 along y: the least is y, a's face axis 1, normal +y.
    AxisQuery q = find_contact_axis(a, box({1.5f, 1.8f, 0}, glm::vec3(1.0f)), 0.0f);
    CHECK(q.axis == 1);
    CHECK(q.separation == Approx(-0.2f));
    CHECK(q.normal.y == Approx(1.0f));
    // Below instead: the normal points from a to b, -y.
    q = find_contact_axis(a, box({0.3f, -1.9f, 0}, glm::vec3(1.0f)), 0.0f);
    CHECK(q.normal.y == Approx(-1.0f));
    CHECK(q.separation == Approx(-0.1f));
    // Apart along x by 0.25: returned at once, separation > 0.
    q = find_contact_axis(a, box({2.25f, 0, 0}, glm::vec3(1.0f)), 0.0f);
    CHECK(q.axis == 0);
    CHECK(q.separation == Approx(0.25f));
    // A cube turned 45 degrees about z, standing on an edge on a's top face:
    // it reaches sqrt(2) below its centre. At y = 1 + sqrt(2) - 0.1 it is 0.1
    // deep along a's y axis. Along b's own (diagonal) face axes it is 0.78
    // deep, and the edge axis a_x x b_z is y again: a's face wins the tie.
    const float r2 = std::sqrt(2.0f);
    q = find_contact_axis(a, box({0, 1 + r2 - 0.1f, 0}, glm::vec3(1.0f), about(45, {0, 0, 1})),
                          0.0f);
    CHECK(q.axis == 1);
    CHECK(q.separation == Approx(-0.1f).margin(1e-5));
}

TEST_CASE("two boxes that only an edge axis separates", "[physics]") {
    // Two cubes of half size 1, each turned so that an edge points at the
    // other: a turned 45 degrees about z (an edge along z on top), b turned 45
    // degrees about x (an edge along x at the bottom). Their edges cross at a
    // right angle along y. Along y, a reaches sqrt(2) up and b sqrt(2) down,
    // so centres 2 sqrt(2) + 0.05 apart leave a 0.05 gap along y = z x x,
    // the cross product of the two edges; every face axis shows overlap.
    const float r2 = std::sqrt(2.0f);
    const OrientedBox a = box({0, 0, 0}, glm::vec3(1.0f), about(45, {0, 0, 1}));
    const OrientedBox b = box({0, 2 * r2 + 0.05f, 0}, glm::vec3(1.0f), about(45, {1, 0, 0}));
    AxisQuery q = find_contact_axis(a, b, 0.0f);
    CHECK(q.axis >= 6);  // an edge-edge axis
    CHECK(q.separation == Approx(0.05f).margin(1e-4));
    CHECK(std::abs(q.normal.y) == Approx(1.0f));
    Manifold m;
    CHECK_FALSE(collide(a, b, 0.0f, m));
    // 0.05 closer: 0.05 deep; the manifold is one point where the edges
    // cross, on the y axis, halfway between them.
    const OrientedBox b2 = box({0, 2 * r2 - 0.05f, 0}, glm::vec3(1.0f), about(45, {1, 0, 0}));
    REQUIRE(collide(a, b2, 0.0f, m));
    CHECK(m.count == 1);
    CHECK(m.normal.y == Approx(1.0f));
    CHECK(m.points[0].depth == Approx(0.05f).margin(1e-4));
    CHECK(glm::length(m.points[0].position - glm::vec3(0, r2 - 0.025f, 0)) < 1e-4f);
    CHECK((m.points[0].id & kEdgeContactBit) != 0);
}

TEST_CASE("a box resting on another: four corners, clipped where it overhangs", "[physics]") {
    const OrientedBox floor = box({0, -0.5f, 0}, {10, 0.5f, 10});
    // A unit cube 2 mm into the floor: its four bottom corners.
    Manifold m;
    REQUIRE(collide(floor, box({0, 0.498f, 0}, glm::vec3(0.5f)), 0.0f, m));
    CHECK(m.count == 4);
    CHECK(m.normal == glm::vec3(0, 1, 0));
    for (uint32_t i = 0; i < 4; ++i) {
        CHECK(m.points[i].depth == Approx(0.002f).margin(1e-6));
        CHECK(reference_face(m.points[i].id) == 2);  // the floor's +y face
        CHECK(incident_face(m.points[i].id) == 3);   // the cube's -y face
        // Halfway between the surfaces: 1 mm below y = 0.
        CHECK(m.points[i].position.y == Approx(-0.001f).margin(1e-6));
    }
    CHECK(has_point_near(m, {0.5f, -0.001f, 0.5f}));
    CHECK(has_point_near(m, {-0.5f, -0.001f, -0.5f}));
    // Four different features: four different ids.
    uint32_t ids[4] = {m.points[0].id, m.points[1].id, m.points[2].id, m.points[3].id};
    std::sort(ids, ids + 4);
    CHECK(std::adjacent_find(ids, ids + 4) == ids + 4);

    // Half hanging over the edge of a smaller box below (its top face from
    // x = -0.5 to 0.5): the cube from x = 0.2 to 1.2 keeps its two corners
    // over the lower box and gains two where its edges cross the lower box's
    // side at x = 0.5 (give or take the clipper's 1 mm tolerance).
    const OrientedBox below = box({0, -0.5f, 0}, glm::vec3(0.5f));
    REQUIRE(collide(below, box({0.7f, 0.495f, 0}, glm::vec3(0.5f)), 0.0f, m));
    CHECK(m.count == 4);
    CHECK(has_point_near(m, {0.2f, -0.0025f, 0.5f}));
    CHECK(has_point_near(m, {0.2f, -0.0025f, -0.5f}));
    CHECK(has_point_near(m, {0.5f, -0.0025f, 0.5f}, 2e-3f));
    CHECK(has_point_near(m, {0.5f, -0.0025f, -0.5f}, 2e-3f));
}

TEST_CASE("a turned box on a box: eight crossings kept as four", "[physics]") {
    // A cube turned 45 degrees about y on a cube of the same size: its bottom
    // square and the top square below cross in an octagon, eight points.
    // Four are kept, spanning as much of it as four can.
    const OrientedBox below = box({0, -0.5f, 0}, glm::vec3(0.5f));
    Manifold m;
    REQUIRE(collide(below, box({0, 0.499f, 0}, glm::vec3(0.5f), about(45, {0, 1, 0})), 0.0f, m));
    CHECK(m.count == 4);
    glm::vec3 centre(0.0f);
    for (uint32_t i = 0; i < 4; ++i) {
        centre += 0.25f * m.points[i].position;
        // On the octagon, whose corners are (+-0.5, +-0.207) and
        // (+-0.207, +-0.5), 0.54 from the middle.
        const glm::vec2 xz(m.points[i].position.x, m.points[i].position.z);
        CHECK(glm::length(xz) > 0.5f - 1e-3f);
    }
    CHECK(glm::length(glm::vec2(centre.x, centre.z)) < 0.15f);
}

TEST_CASE("feature ids stay the same while a contact slides a little", "[physics]") {
    const OrientedBox floor = box({0, -0.5f, 0}, {10, 0.5f, 10});
    Manifold before, after;
    REQUIRE(
        collide(floor, box({0, 0.498f, 0}, glm::vec3(0.5f), about(3, {0, 1, 0})), 0.0f, before));
    REQUIRE(collide(floor, box({0.01f, 0.497f, 0.02f}, glm::vec3(0.5f), about(4, {0, 1, 0})), 0.0f,
                    after));
    REQUIRE(before.count == after.count);
    for (uint32_t i = 0; i < before.count; ++i) CHECK(before.points[i].id == after.points[i].id);
    // Lying on another face, the cube's points come from another face: new ids.
    Manifold turned;
    REQUIRE(
        collide(floor, box({0, 0.498f, 0}, glm::vec3(0.5f), about(90, {1, 0, 0})), 0.0f, turned));
    CHECK(incident_face(turned.points[0].id) != incident_face(before.points[0].id));
}

TEST_CASE("sort-and-sweep finds exactly the pairs brute force finds", "[physics]") {
    for (uint32_t seed : {1u, 2u, 3u}) {
        for (float side : {4.0f, 12.0f, 40.0f}) {  // dense, medium, sparse
            for (uint32_t count : {10u, 200u, 1500u}) {
                Random random{seed * 7919u + count};
                std::vector<Body> bodies(count);
                std::vector<Aabb> aabbs(count);
                for (uint32_t i = 0; i < count; ++i) {
                    Body& b = bodies[i];
                    b.position = {random(-side, side), random(-side, side), random(-side, side)};
                    b.half_extents = {random(0.1f, 1), random(0.1f, 1), random(0.1f, 1)};
                    b.orientation = random_orientation(random);
                    b.inverse_mass = i % 5 == 0 ? 0.0f : 1.0f;  // every fifth static
                    aabbs[i] = world_aabb(b.position, rotation(b), b.half_extents, 0.005f);
                    // Every seventh sharing the last one's lowest x exactly:
                    // ties in the sort.
                    if (i % 7 == 6) {
                        const float shift = aabbs[i - 1].low.x - aabbs[i].low.x;
                        aabbs[i].low.x += shift;
                        aabbs[i].high.x += shift;
                    }
                }
                std::vector<Pair> brute, sweep;
                find_pairs_brute_force(aabbs, bodies, brute);
                SweepAndPrune sap;
                sap.find_pairs(aabbs, bodies, sweep);
                INFO("seed " << seed << ", side " << side << ", " << count << " boxes, "
                             << brute.size() << " pairs");
                CHECK(sweep == brute);
                // And again after the boxes move: the kept order is re-sorted.
                for (Aabb& box : aabbs) {
                    const float dx = random(-1, 1);
                    box.low.x += dx;
                    box.high.x += dx;
                }
                find_pairs_brute_force(aabbs, bodies, brute);
                sap.find_pairs(aabbs, bodies, sweep);
                CHECK(sweep == brute);
                for (const Pair& pair : brute)
                    CHECK_FALSE((bodies[pair.a].is_static() && bodies[pair.b].is_static()));
            }
        }
    }
}
