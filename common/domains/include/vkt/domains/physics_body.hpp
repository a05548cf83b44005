#pragma once
// A rigid box that turns, taught by chapter 14: its state (where it is, how it
// is turned, how fast it moves and spins), its mass and inertia, the
// gyroscopic term that turns its spin axis, and the move with the velocities
// the contact solver has corrected.
//
// Plain C++ and glm: no Vulkan here.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>

namespace vkt::physics {

// [body]
struct Body {
    glm::vec3 position{0.0f};                       // the centre of mass, metres
    glm::quat orientation{1.0f, 0.0f, 0.0f, 0.0f};  // body frame -> world, unit length
    glm::vec3 velocity{0.0f};                       // of the centre, metres per second
    glm::vec3 angular_velocity{0.0f};               // world axis * radians per second
    glm::vec3 half_extents{0.5f};                   // half the size along the body's x, y, z
    float inverse_mass = 0.0f;                      // 1 / kg; 0: static, never moves
    glm::vec3 inverse_inertia{0.0f};                // 1 / the principal moments (body frame)
    float sleep_time = 0.0f;                        // seconds it has been slow enough to sleep
    uint32_t awake = 1;   // 0: asleep (not simulated until something touches it)
    uint32_t island = 0;  // asleep: the island it fell asleep with (its lowest body index)

    bool is_static() const { return inverse_mass == 0.0f; }
    // Moving: neither static nor asleep.
    bool is_active() const { return inverse_mass > 0.0f && awake != 0; }
};
// [/body]
static_assert(sizeof(Body) == 23 * sizeof(float), "no padding: the tests memcmp bodies");

// [box-inertia]
// The inverse of a solid box's principal moments of inertia about its centre,
// for mass m and half extents (a, b, c): I_x = m (b^2 + c^2) / 3, and so on
// (book/14b_inertia.md derives it). Mass 0 (static) gives 0: infinitely heavy.
glm::vec3 box_inverse_inertia(glm::vec3 half_extents, float mass);
// [/box-inertia]

// The rotation matrix of a body: its columns are the body's own x, y and z
// axes, in world space.
inline glm::mat3 rotation(const Body& body) {
    return glm::mat3_cast(body.orientation);
}

// [world-inertia]
// The inverse inertia tensor in world space, R I^-1 R^T: turn a world vector
// into the body frame (R^T), scale by the body's inverse moments, turn back.
glm::mat3 world_inverse_inertia(const glm::mat3& rotation, glm::vec3 inverse_inertia);
// [/world-inertia]

// The gyroscopic term, once a step for a moving body: a box spinning about
// anything but a principal axis changes its spin axis by itself. Solved
// implicitly (stable), then scaled to keep the spin's energy (the term does
// no work).
void gyroscopic_step(Body& body, float dt);

// Move and turn with the given velocities (the solver's, once each
// sub-step), then renormalise the
// quaternion so that rounding never lets it drift away from unit length.
void integrate_position(Body& body, glm::vec3 velocity, glm::vec3 angular_velocity, float dt);

// Energies, for the tests and the book: m v^2 / 2 + w . I w / 2, and m g h
// with h measured along -gravity from the origin.
double kinetic_energy(const Body& body);
double potential_energy(const Body& body, glm::vec3 gravity);

}  // namespace vkt::physics
