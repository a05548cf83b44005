#include "vkt/domains/physics_body.hpp"

#include <cmath>

namespace vkt::physics {

glm::vec3 box_inverse_inertia(glm::vec3 h, float mass) {
    if (mass <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 moments =
        mass / 3.0f *
        glm::vec3(h.y * h.y + h.z * h.z, h.x * h.x + h.z * h.z, h.x * h.x + h.y * h.y);
    return 1.0f / moments;
}

// [world-inertia-code]
glm::mat3 world_inverse_inertia(const glm::mat3& r, glm::vec3 inverse_inertia) {
    // R diag(i) R^T, written out: scale R's columns by i, then multiply by R^T.
    const glm::mat3 scaled(r[0] * inverse_inertia.x, r[1] * inverse_inertia.y,
                           r[2] * inverse_inertia.z);
    return scaled * glm::transpose(r);
}
// [/world-inertia-code]

namespace {
// The cross-product matrix: skew(a) * b == cross(a, b). glm is column-major.
glm::mat3 skew(glm::vec3 a) {
    return glm::mat3(glm::vec3(0.0f, a.z, -a.y), glm::vec3(-a.z, 0.0f, a.x),
                     glm::vec3(a.y, -a.x, 0.0f));
}
}  // namespace

// [gyroscopic]
void gyroscopic_step(Body& body, float dt) {
    // The gyroscopic term, in the body frame where the inertia I is diagonal:
    // Euler's equation without torque, I dw/dt = -w x (I w). One Newton step of
    // its implicit (backward Euler) form: f(w) = I (w - w0) + dt w x (I w) = 0,
    // Jacobian J = I + dt (skew(w) I - skew(I w)). Implicit: it cannot blow
    // up where an explicit step would add energy.
    const glm::vec3 moments = 1.0f / body.inverse_inertia;
    const glm::mat3 inertia(glm::vec3(moments.x, 0, 0), glm::vec3(0, moments.y, 0),
                            glm::vec3(0, 0, moments.z));
    const glm::vec3 w0 = glm::inverse(body.orientation) * body.angular_velocity;
    const glm::vec3 f = dt * glm::cross(w0, moments * w0);
    const glm::mat3 jacobian = inertia + dt * (skew(w0) * inertia - skew(moments * w0));
    glm::vec3 w = w0 - glm::inverse(jacobian) * f;
    // But it damps: a fast spin about the middle axis would lose half its
    // energy in 20 s. The term does no work (w . (w x I w) = 0), so the
    // energy w . I w / 2 must stay: scale the new spin back to it.
    const float before = glm::dot(w0, moments * w0), after = glm::dot(w, moments * w);
    if (after > 0.0f) w *= std::sqrt(before / after);
    body.angular_velocity = body.orientation * w;
}
// [/gyroscopic]

// [integrate-position]
void integrate_position(Body& body, glm::vec3 velocity, glm::vec3 angular_velocity, float dt) {
    body.position += velocity * dt;
    // dq/dt = (0, w) q / 2: the quaternion's derivative under spin w. One Euler
    // step leaves q slightly longer than 1; normalising puts it back.
    const glm::quat spin(0.0f, angular_velocity.x, angular_velocity.y, angular_velocity.z);
    body.orientation = glm::normalize(body.orientation + (0.5f * dt) * (spin * body.orientation));
}
// [/integrate-position]

double kinetic_energy(const Body& body) {
    if (body.is_static()) return 0.0;
    const glm::vec3 w = glm::inverse(body.orientation) * body.angular_velocity;  // body frame
    const glm::vec3 moments = 1.0f / body.inverse_inertia;
    return 0.5 * double(glm::dot(body.velocity, body.velocity)) / double(body.inverse_mass) +
           0.5 * double(glm::dot(w, moments * w));
}

double potential_energy(const Body& body, glm::vec3 gravity) {
    if (body.is_static()) return 0.0;
    return -double(glm::dot(gravity, body.position)) / double(body.inverse_mass);
}

}  // namespace vkt::physics
