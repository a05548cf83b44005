#include "vkt/scene/fps_camera.hpp"

#include <algorithm>
#include <cmath>

namespace vkt {

float clamp_pitch(float pitch) {
    return std::clamp(pitch, -FpsCamera::max_pitch, FpsCamera::max_pitch);
}

// [forward]
// Start from (0, 0, -1), the way an unturned camera looks. Pitch tilts it up
// in the y-z plane: (0, sin p, -cos p). Yaw then turns that about world +y,
// carrying the horizontal part, of length cos p, from -z towards +x.
glm::vec3 FpsCamera::forward() const {
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw)};
}

// cross(forward, world up), normalised: the cos p factor divides out, and the
// result is horizontal whatever the pitch (no roll). Defined as long as
// cos p != 0, which the pitch clamp guarantees.
glm::vec3 FpsCamera::right() const {
    return {std::cos(yaw), 0.0f, std::sin(yaw)};
}

// Perpendicular to both, unit length because they are perpendicular unit vectors.
glm::vec3 FpsCamera::up() const {
    return glm::cross(right(), forward());
}
// [/forward]

glm::vec3 FpsCamera::walk_forward() const {
    return {std::sin(yaw), 0.0f, -std::cos(yaw)};
}

// [view]
// The camera's placement in the world is a rotation R, whose columns are the
// camera's axes (right, up, and -forward, since it looks down its own -z),
// followed by a translation to `position`: world = R * camera + position.
// The view matrix undoes that: camera = R^T * (world - position)
//                                     = R^T * world - R^T * position.
// R is orthonormal, so its inverse is its transpose: the axes become rows.
glm::mat4 FpsCamera::view() const {
    const glm::vec3 r = right(), u = up(), b = -forward();  // b: the camera's +z, backwards
    // Rows right, up, back; glm is column-major, m[column][row].
    glm::mat4 m(1.0f);
    m[0][0] = r.x, m[1][0] = r.y, m[2][0] = r.z;
    m[0][1] = u.x, m[1][1] = u.y, m[2][1] = u.z;
    m[0][2] = b.x, m[1][2] = b.y, m[2][2] = b.z;
    m[3] = glm::vec4(-glm::dot(r, position), -glm::dot(u, position), -glm::dot(b, position), 1.0f);
    return m;
}
// [/view]

// [look]
void FpsCamera::look(double mouse_dx, double mouse_dy, float sensitivity) {
    constexpr float two_pi = 2.0f * std::numbers::pi_v<float>;
    // Keep yaw small: after hours of turning the same way a float angle in
    // the thousands would lose precision, and sin and cos do not care.
    yaw = std::remainder(yaw + float(mouse_dx) * sensitivity, two_pi);
    // Screen y points down: moving the mouse down looks down.
    pitch = clamp_pitch(pitch - float(mouse_dy) * sensitivity);
}
// [/look]

// [move]
glm::vec3 FpsCamera::move_direction(const Input& input) const {
    auto axis = [&](int plus, int minus) {
        return float(input.down(plus)) - float(input.down(minus));
    };
    const glm::vec3 wish = axis('W', 'S') * walk_forward() + axis('D', 'A') * right() +
                           axis('E', 'Q') * glm::vec3(0.0f, 1.0f, 0.0f);
    // W and D together give a vector of length sqrt(2); normalising it keeps
    // the diagonal as fast as a straight line. Zero stays zero.
    const float length = glm::length(wish);
    return length > 0.0f ? wish / length : glm::vec3(0.0f);
}

void FpsCamera::update(const Input& input, float dt, float speed, float sensitivity) {
    // Movement made while the cursor was captured counts even if the cursor
    // was released later in the same frame (Escape): the snapshot holds only
    // such movement, and it holds it whatever cursor_captured says now.
    look(input.mouse_dx, input.mouse_dy, sensitivity);
    // Metres per second times seconds: the same walk at 30 or 240 frames/s.
    position += move_direction(input) * speed * std::max(dt, 0.0f);
}
// [/move]

}  // namespace vkt
