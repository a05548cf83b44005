// The matrices of chapter 08 (vkt/scene/camera_math.hpp), against points worked out
// by hand.
#include "vkt/scene/camera_math.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <numbers>

using Catch::Approx;

namespace {
constexpr float pi = std::numbers::pi_v<float>;
}

TEST_CASE("vulkan_perspective maps the near plane to depth 0 and the far plane to 1",
          "[camera_math]") {
    const glm::mat4 proj = vkt::vulkan_perspective(pi / 3.0f, 4.0f / 3.0f, 0.5f, 40.0f);
    // The camera looks down -z: the near plane is z = -0.5, the far z = -40.
    CHECK(vkt::project_to_ndc(proj, {0.0f, 0.0f, -0.5f}).z == Approx(0.0f).margin(1e-6));
    CHECK(vkt::project_to_ndc(proj, {0.1f, -0.2f, -0.5f}).z == Approx(0.0f).margin(1e-6));
    CHECK(vkt::project_to_ndc(proj, {0.0f, 0.0f, -40.0f}).z == Approx(1.0f).epsilon(1e-5));
    // Halfway in z is not halfway in depth: depth = f(z - n) / (z (f - n))
    // with z the distance; at z = 1: 40 * 0.5 / (1 * 39.5) = 0.50633.
    CHECK(vkt::project_to_ndc(proj, {0.0f, 0.0f, -1.0f}).z == Approx(20.0f / 39.5f).epsilon(1e-5));
}

TEST_CASE("vulkan_perspective: the edge of the field of view is the edge of the screen",
          "[camera_math]") {
    // fovy 90 degrees: at distance 2 the top edge is y = 2, the right edge
    // x = 2 * aspect. Up in the world is negative NDC y: up on a Vulkan screen.
    const glm::mat4 proj = vkt::vulkan_perspective(pi / 2.0f, 2.0f, 0.1f, 10.0f);
    const glm::vec3 top = vkt::project_to_ndc(proj, {0.0f, 2.0f, -2.0f});
    CHECK(top.x == Approx(0.0f).margin(1e-6));
    CHECK(top.y == Approx(-1.0f));
    const glm::vec3 right = vkt::project_to_ndc(proj, {4.0f, 0.0f, -2.0f});
    CHECK(right.x == Approx(1.0f));
    CHECK(right.y == Approx(0.0f).margin(1e-6));
}

TEST_CASE("a look-at target lands at the centre, world up goes up on the screen", "[camera_math]") {
    const glm::vec3 eye{3.0f, 4.0f, 5.0f};
    const glm::vec3 target{-1.0f, 0.5f, 0.0f};
    const glm::mat4 view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 proj = vkt::vulkan_perspective(pi / 4.0f, 1.5f, 0.1f, 100.0f);
    const glm::vec3 centre = vkt::project_to_ndc(proj * view, target);
    CHECK(centre.x == Approx(0.0f).margin(1e-5));
    CHECK(centre.y == Approx(0.0f).margin(1e-5));
    CHECK(centre.z > 0.0f);
    CHECK(centre.z < 1.0f);
    // A point straight above the target is above the centre: NDC y < 0 (y down).
    const glm::vec3 above = vkt::project_to_ndc(proj * view, target + glm::vec3(0.0f, 1.0f, 0.0f));
    CHECK(above.y < -0.01f);
    // And one to the camera's right (here +x and -z, seen from +x+z) has NDC x > 0.
    const glm::vec3 right_dir = glm::normalize(glm::cross(target - eye, glm::vec3(0, 1, 0)));
    CHECK(vkt::project_to_ndc(proj * view, target + right_dir).x > 0.01f);
}

TEST_CASE("transform is T * R * S: scale, then rotate, then translate", "[camera_math]") {
    // Scale (2, 3, 1), rotate 90 degrees about +z, translate (10, 20, 30).
    // (1, 1, 0) -> scale -> (2, 3, 0) -> rotate (x, y) -> (-y, x) -> (-3, 2, 0)
    // -> translate -> (7, 22, 30).
    const glm::mat4 m =
        vkt::transform({10.0f, 20.0f, 30.0f}, pi / 2.0f, {0.0f, 0.0f, 1.0f}, {2.0f, 3.0f, 1.0f});
    const glm::vec4 p = m * glm::vec4(1.0f, 1.0f, 0.0f, 1.0f);
    CHECK(p.x == Approx(7.0f));
    CHECK(p.y == Approx(22.0f));
    CHECK(p.z == Approx(30.0f));
    CHECK(p.w == Approx(1.0f));
    // The other order (scale after rotating) gives a different point: (-2, 3, 0) + T.
    const glm::mat4 wrong = glm::translate(glm::mat4(1.0f), {10.0f, 20.0f, 30.0f}) *
                            glm::scale(glm::mat4(1.0f), {2.0f, 3.0f, 1.0f}) *
                            glm::rotate(glm::mat4(1.0f), pi / 2.0f, {0.0f, 0.0f, 1.0f});
    const glm::vec4 q = wrong * glm::vec4(1.0f, 1.0f, 0.0f, 1.0f);
    CHECK(q.x == Approx(8.0f));
    CHECK(q.y == Approx(23.0f));
    // Directions (w = 0) are not translated.
    const glm::vec4 d = m * glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    CHECK(d.x == Approx(0.0f).margin(1e-6));
    CHECK(d.y == Approx(2.0f));
    CHECK(d.w == 0.0f);
}
