#pragma once
// The narrow phase of chapter 14: do two turned boxes touch, and where? The
// separating axis theorem over 15 axes finds the axis of least penetration;
// clipping one box's face against the other's gives up to four contact
// points (a contact manifold), each with a feature id that names the corner,
// edge and face it came from, so that the same contact can be recognised
// next step and start from last step's impulse.
//
// Plain C++ and glm: no Vulkan here.

#include "vkt/domains/physics_body.hpp"

#include <array>
#include <cstdint>

namespace vkt::physics {

// A box as the narrow phase sees it: centre, axes (the columns of rotation)
// and half extents. The world computes these once per step for every body.
struct OrientedBox {
    glm::vec3 centre{0.0f};
    glm::mat3 rotation{1.0f};
    glm::vec3 half_extents{0.5f};
};
inline OrientedBox oriented_box(const Body& body) {
    return {body.position, rotation(body), body.half_extents};
}

// [contact-point]
struct ContactPoint {
    glm::vec3 position{0.0f};  // world, halfway between the two surfaces
    float depth = 0.0f;        // overlap along the normal: > 0 inside, < 0 a gap within the margin
    uint32_t id = 0;           // feature id: which corner, edge and faces made this point
    // The solver's accumulated impulses at this point, kept for warm starting
    // the same point (same id) next step.
    float normal_impulse = 0.0f;
    glm::vec3 friction_impulse{0.0f};  // world space: the friction axes turn with the normal
};

struct Manifold {
    uint32_t a = 0, b = 0;   // the bodies, a < b
    glm::vec3 normal{0.0f};  // unit, from a towards b: pushing b along it separates them
    uint32_t count = 0;      // 1 to 4 points
    std::array<ContactPoint, 4> points{};
};
// [/contact-point]

// [axis-query]
// One of the 15 candidate axes: 0..2 a's face normals, 3..5 b's, 6 + 3i + j
// the cross product of a's axis i and b's axis j (an edge of each).
struct AxisQuery {
    float separation = 0.0f;  // the boxes' gap along it: > 0 apart, < 0 overlapping by -separation
    int axis = -1;
    glm::vec3 normal{0.0f};  // unit, from a towards b
};
// [/axis-query]

// The separating axis test. If some axis separates the boxes by more than
// `margin`, returns it (the first found: separation > margin). Otherwise
// returns the axis of least penetration, preferring a's faces, then b's, then
// edges unless one is clearly better (so that a resting box keeps the same
// axis and the same contact points from step to step).
AxisQuery find_contact_axis(const OrientedBox& a, const OrientedBox& b, float margin);

// The narrow phase: true when the boxes are within `margin` of each other, with
// `out`'s normal and points filled in (out.a, out.b and the impulses are left
// for the caller).
bool collide(const OrientedBox& a, const OrientedBox& b, float margin, Manifold& out);

// Where a body is and how it is turned, at one moment.
struct Pose {
    glm::vec3 position{0.0f};
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};
};

// Continuous collision: a box of half extents `half` moves from `from` to
// `to` in one step (its centre along a line, its turn blended between the
// two). Returns the first fraction of the move, in [0, 1), at which the gap
// between it and the box `fixed` (as the separating axes measure it) has
// closed to `target`; 1 if it never does, or if the gap is already that
// small at the start (the ordinary contacts have that case).
float time_of_impact(const OrientedBox& fixed, glm::vec3 half, const Pose& from, const Pose& to,
                     float target);

// Feature ids, for the tests: a face contact's id holds the reference face
// (0..5: +x, -x, +y, -y, +z, -z of that box), the incident face, whether the
// reference face is b's, and which two of the 8 lines (the incident face's 4
// edges, the reference face's 4 sides) cross at the point.
constexpr uint32_t kEdgeContactBit = 0x80000000u;
constexpr uint32_t kReferenceIsB = 0x40000000u;
inline uint32_t reference_face(uint32_t id) {
    return (id >> 12) & 7u;
}
inline uint32_t incident_face(uint32_t id) {
    return (id >> 8) & 7u;
}

}  // namespace vkt::physics
