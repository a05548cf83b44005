#pragma once
// A first-person camera: a position and two angles, taught in chapter 11.
//
// Conventions (the conventions appendix): world +y is up, the camera looks
// down its own -z. yaw turns about world +y: 0 looks down world -z, a positive
// yaw turns right (towards +x). pitch tilts up (positive) or down, and is kept
// within +-max_pitch, short of straight up or down, where "right" would be
// undefined. There is no roll: the horizon stays level.

#include "vkt/frame/input.hpp"

#include <glm/glm.hpp>

#include <numbers>

namespace vkt {

// [state]
struct FpsCamera {
    glm::vec3 position{0.0f};
    float yaw = 0.0f;    // radians
    float pitch = 0.0f;  // radians, within +-max_pitch

    // 89 degrees.
    static constexpr float max_pitch = 89.0f * std::numbers::pi_v<float> / 180.0f;
    // [/state]

    // Unit vectors in world space. forward: where the camera looks,
    // (cos p sin y, sin p, -cos p cos y). right: horizontal,
    // (cos y, 0, sin y) = normalize(cross(forward, world up)). up:
    // cross(right, forward), tilted back with the pitch.
    glm::vec3 forward() const;
    glm::vec3 right() const;
    glm::vec3 up() const;
    // forward flattened onto the floor, (sin y, 0, -cos y): where W walks.
    glm::vec3 walk_forward() const;

    // camera_from_world: the inverse of the camera's placement in the world,
    // written out (rows right, up, -forward; translation -R^T position). The
    // same matrix as glm::lookAt(position, position + forward(), {0, 1, 0}).
    glm::mat4 view() const;

    // Mouse look: mouse_dx pixels to the right turn right, mouse_dy pixels
    // down (screen y points down) look down; `sensitivity` radians per pixel.
    // The pitch is clamped, the yaw wrapped into [-pi, pi].
    void look(double mouse_dx, double mouse_dy, float sensitivity);

    // One frame of input: look with the mouse movement, then move `speed`
    // metres per second for `dt` seconds in the direction of
    // move_direction(input). dt below 0 counts as 0. The runner's snapshot
    // holds mouse movement only from while the cursor was captured (see
    // vkt::InputAccumulator), so a free cursor turns nothing.
    void update(const Input& input, float dt, float speed, float sensitivity);

    // The direction the held keys ask for, in world space: W and S along
    // walk_forward(), D and A along right(), E and Q along world up. Unit
    // length (a diagonal is no faster than a straight line), or zero when no
    // key is held or opposite keys cancel.
    glm::vec3 move_direction(const Input& input) const;
};

// A pitch clamped to +-FpsCamera::max_pitch.
float clamp_pitch(float pitch);

}  // namespace vkt
