// The first-person camera of chapter 11 (vkt/scene/fps_camera.hpp), against values
// worked out by hand and against glm::lookAt.
#include "vkt/frame/input.hpp"
#include "vkt/scene/fps_camera.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

using Catch::Approx;

namespace {

constexpr float pi = std::numbers::pi_v<float>;
constexpr float degrees = pi / 180.0f;

void check_vec(glm::vec3 got, glm::vec3 want, float margin = 1e-6f) {
    INFO("got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", "
                 << want.y << ", " << want.z << ")");
    CHECK(got.x == Approx(want.x).margin(margin));
    CHECK(got.y == Approx(want.y).margin(margin));
    CHECK(got.z == Approx(want.z).margin(margin));
}

vkt::FpsCamera pose(glm::vec3 position, float yaw_degrees, float pitch_degrees) {
    return {position, yaw_degrees * degrees, pitch_degrees * degrees};
}

vkt::Input holding(std::initializer_list<int> keys) {
    vkt::Input input;
    for (int key : keys) input.held[size_t(key)] = true;
    return input;
}

}  // namespace

TEST_CASE("forward from yaw and pitch, on hand-worked angles", "[camera]") {
    // forward = (cos p sin y, sin p, -cos p cos y).
    check_vec(pose({}, 0, 0).forward(), {0, 0, -1});               // unturned: down -z
    check_vec(pose({}, 90, 0).forward(), {1, 0, 0});               // a quarter turn right: +x
    check_vec(pose({}, -90, 0).forward(), {-1, 0, 0});             // a quarter turn left: -x
    check_vec(pose({}, 180, 0).forward(), {0, 0, 1});              // turned round: +z
    check_vec(pose({}, 30, 0).forward(), {0.5f, 0, -0.8660254f});  // sin 30, -cos 30
    check_vec(pose({}, 0, 45).forward(), {0, 0.7071068f, -0.7071068f});
    check_vec(pose({}, 90, 30).forward(), {0.8660254f, 0.5f, 0});  // cos 30, sin 30
    // yaw 45, pitch 60: cos 60 = 0.5 shared out by sin 45 and cos 45.
    check_vec(pose({}, 45, 60).forward(), {0.3535534f, 0.8660254f, -0.3535534f});
}

TEST_CASE("right is horizontal and up is tilted with the pitch", "[camera]") {
    // yaw 90, pitch 30: looking along +x and up. Right is +z whatever the
    // pitch; up = cross(right, forward) = (0,0,1) x (0.866, 0.5, 0)
    // = (-0.5, 0.866, 0): tilted back, away from where the camera looks.
    const vkt::FpsCamera camera = pose({}, 90, 30);
    check_vec(camera.right(), {0, 0, 1});
    check_vec(camera.up(), {-0.5f, 0.8660254f, 0});
    check_vec(camera.walk_forward(), {1, 0, 0});
    // A right-handed orthonormal frame at any angle.
    for (float yaw = -180; yaw <= 180; yaw += 37)
        for (float pitch = -89; pitch <= 89; pitch += 22.25f) {
            const vkt::FpsCamera c = pose({}, yaw, pitch);
            CHECK(glm::length(c.forward()) == Approx(1.0f));
            CHECK(glm::length(c.right()) == Approx(1.0f));
            CHECK(glm::length(c.up()) == Approx(1.0f));
            CHECK(glm::dot(c.forward(), c.right()) == Approx(0.0f).margin(1e-6));
            CHECK(glm::dot(c.forward(), c.up()) == Approx(0.0f).margin(1e-6));
            CHECK(c.right().y == 0.0f);  // no roll: the horizon stays level
            check_vec(glm::cross(c.right(), c.up()), -c.forward(), 1e-5f);
        }
}

TEST_CASE("pitch is clamped short of the poles", "[camera]") {
    vkt::FpsCamera camera;
    CHECK(vkt::FpsCamera::max_pitch == Approx(89.0f * degrees));
    CHECK(vkt::clamp_pitch(0.3f) == 0.3f);
    CHECK(vkt::clamp_pitch(2.0f) == vkt::FpsCamera::max_pitch);
    CHECK(vkt::clamp_pitch(-2.0f) == -vkt::FpsCamera::max_pitch);

    // The mouse pushed far up (screen y negative): straight up is never
    // reached, so right and the view matrix stay well defined.
    camera.look(0.0, -100000.0, 0.002f);
    CHECK(camera.pitch == vkt::FpsCamera::max_pitch);
    CHECK(camera.forward().y == Approx(std::sin(89.0f * degrees)));
    check_vec(camera.right(), {1, 0, 0});
    const glm::mat4 view = camera.view();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(std::isfinite(view[c][r]));
    // And far down.
    camera.look(0.0, 300000.0, 0.002f);
    CHECK(camera.pitch == -vkt::FpsCamera::max_pitch);
    // Yaw is not clamped but wrapped: three and a bit turns right end up at
    // the bit, looking the same way.
    vkt::FpsCamera turning;
    turning.look((6.0 * double(pi) + 0.5) / 0.001, 0.0, 0.001f);
    CHECK(turning.yaw == Approx(0.5f).margin(1e-3));
    CHECK(std::abs(turning.yaw) <= pi);
}

TEST_CASE("the mouse turns the way it moves, and only while the cursor is captured", "[camera]") {
    vkt::Input input;
    input.mouse_dx = 100;  // right
    input.mouse_dy = 50;   // down (screen y)
    input.cursor_captured = true;
    vkt::FpsCamera camera;
    camera.update(input, 1.0f / 60, 3.0f, 0.002f);
    CHECK(camera.yaw == Approx(0.2f));     // 100 px * 0.002 rad/px, to the right
    CHECK(camera.pitch == Approx(-0.1f));  // 50 px down: looking down
    CHECK(camera.forward().x > 0.0f);
    CHECK(camera.forward().y < 0.0f);

    // Through the runner's accumulator (vkt/frame/input.hpp), as in a window. A free
    // cursor's movement is the user's, not the camera's.
    vkt::InputAccumulator window;
    window.cursor(10, 10);
    window.cursor(300, 200);
    vkt::FpsCamera free_cursor;
    free_cursor.update(window.take(), 1.0f / 60, 3.0f, 0.002f);
    CHECK(free_cursor.yaw == 0.0f);
    CHECK(free_cursor.pitch == 0.0f);
    // Captured: 100 px right. Then, in the same frame, Escape releases the
    // cursor: the movement made while it was captured still turns the camera.
    window.set_captured(true);
    window.cursor(400, 300);  // the first position after capture: no movement
    window.cursor(500, 300);
    window.set_captured(false);
    window.cursor(900, 900);  // free again: not counted
    const vkt::Input frame = window.take();
    CHECK_FALSE(frame.cursor_captured);
    vkt::FpsCamera released;
    released.update(frame, 1.0f / 60, 3.0f, 0.002f);
    CHECK(released.yaw == Approx(0.2f));
    CHECK(released.pitch == 0.0f);
}

TEST_CASE("the view matrix of a known pose, worked by hand", "[camera]") {
    // At (1, 2, 3), looking along +x (yaw 90, pitch 0): right = (0, 0, 1),
    // up = (0, 1, 0), backwards = -forward = (-1, 0, 0). Those are the rows;
    // the translation is -(right . p, up . p, back . p) = (-3, -2, 1). So
    // view * (x, y, z, 1) = (z - 3, y - 2, 1 - x).
    const glm::mat4 view = pose({1, 2, 3}, 90, 0).view();
    const glm::mat4 want(glm::vec4(0, 0, -1, 0),  // columns
                         glm::vec4(0, 1, 0, 0), glm::vec4(1, 0, 0, 0), glm::vec4(-3, -2, 1, 1));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            INFO("column " << c << ", row " << r);
            CHECK(view[c][r] == Approx(want[c][r]).margin(1e-6));
        }
    // 4 m straight ahead lands on the camera's -z axis; a point 1 m to the
    // camera's right (+z here) on its +x axis; the eye at the origin.
    check_vec(glm::vec3(view * glm::vec4(5, 2, 3, 1)), {0, 0, -4});
    check_vec(glm::vec3(view * glm::vec4(1, 2, 4, 1)), {1, 0, 0});
    check_vec(glm::vec3(view * glm::vec4(1, 2, 3, 1)), {0, 0, 0});

    // At (0, 1, 0), yaw 0, looking 30 degrees up: forward (0, 0.5, -0.866),
    // up (0, 0.866, 0.5), back (0, -0.5, 0.866); the translation is
    // (0, -0.866, 0.5). The point 2 m along forward, (0, 2, -1.732):
    // up row 0.866 * 2 + 0.5 * -1.732 - 0.866 = 0, back row
    // -0.5 * 2 + 0.866 * -1.732 + 0.5 = -2: straight ahead at distance 2.
    const vkt::FpsCamera up30 = pose({0, 1, 0}, 0, 30);
    const glm::mat4 tilted = up30.view();
    CHECK(tilted[3][1] == Approx(-0.8660254f));
    CHECK(tilted[3][2] == Approx(0.5f));
    check_vec(glm::vec3(tilted * glm::vec4(0, 2, -1.7320508f, 1)), {0, 0, -2}, 1e-5f);
}

TEST_CASE("the written-out view matrix is glm::lookAt and the inverse of the placement",
          "[camera]") {
    for (float yaw = -175; yaw <= 180; yaw += 35)
        for (float pitch : {-89.0f, -60.0f, -30.0f, 0.0f, 20.0f, 45.0f, 75.0f, 89.0f}) {
            const vkt::FpsCamera camera = pose({1.5f, -0.5f, 7.25f}, yaw, pitch);
            // Near the poles glm::lookAt computes right as cross(forward, up) of
            // two nearly parallel vectors (length cos 89 = 0.017) and loses
            // about two digits; ours takes right from the yaw and does not.
            const float margin = std::abs(pitch) > 85 ? 2e-4f : 1e-5f;
            const glm::mat4 view = camera.view();
            const glm::mat4 look = glm::lookAt(camera.position, camera.position + camera.forward(),
                                               glm::vec3(0, 1, 0));
            // The placement: columns right, up, back and the position.
            const glm::mat4 placement(glm::vec4(camera.right(), 0), glm::vec4(camera.up(), 0),
                                      glm::vec4(-camera.forward(), 0),
                                      glm::vec4(camera.position, 1));
            const glm::mat4 identity = view * placement;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) {
                    INFO("yaw " << yaw << ", pitch " << pitch << ", column " << c << ", row " << r);
                    CHECK(view[c][r] == Approx(look[c][r]).margin(margin));
                    CHECK(identity[c][r] == Approx(c == r ? 1.0f : 0.0f).margin(1e-5));
                }
        }
}

TEST_CASE("diagonal movement is normalised", "[camera]") {
    const vkt::FpsCamera camera;  // at the origin, looking down -z
    check_vec(camera.move_direction(holding({'W'})), {0, 0, -1});
    check_vec(camera.move_direction(holding({'S'})), {0, 0, 1});
    check_vec(camera.move_direction(holding({'D'})), {1, 0, 0});
    check_vec(camera.move_direction(holding({'A'})), {-1, 0, 0});
    check_vec(camera.move_direction(holding({'E'})), {0, 1, 0});
    check_vec(camera.move_direction(holding({'Q'})), {0, -1, 0});
    // W + D: (1, 0, -1) / sqrt 2, not (1, 0, -1).
    check_vec(camera.move_direction(holding({'W', 'D'})), {0.7071068f, 0, -0.7071068f});
    // Three keys: each component 1 / sqrt 3.
    check_vec(camera.move_direction(holding({'W', 'D', 'E'})),
              {0.5773503f, 0.5773503f, -0.5773503f});
    // Opposite keys cancel, and nothing held is no movement (not NaN).
    check_vec(camera.move_direction(holding({'W', 'S'})), {0, 0, 0});
    check_vec(camera.move_direction(holding({'W', 'S', 'A', 'D', 'Q', 'E'})), {0, 0, 0});
    check_vec(camera.move_direction(vkt::Input{}), {0, 0, 0});

    // The distance walked in one second is the speed, straight or diagonal.
    vkt::FpsCamera straight, diagonal;
    straight.update(holding({'W'}), 1.0f, 4.0f, 0.002f);
    diagonal.update(holding({'W', 'A'}), 1.0f, 4.0f, 0.002f);
    CHECK(glm::length(straight.position) == Approx(4.0f));
    CHECK(glm::length(diagonal.position) == Approx(4.0f));
    check_vec(diagonal.position, {-2.8284271f, 0, -2.8284271f}, 1e-5f);
}

TEST_CASE("walking stays level whatever the pitch", "[camera]") {
    vkt::FpsCamera camera = pose({0, 1.7f, 0}, 90, -60);  // looking down at the floor
    camera.update(holding({'W'}), 0.5f, 2.0f, 0.002f);
    check_vec(camera.position, {1, 1.7f, 0});  // 1 m along +x, no lower
}

TEST_CASE("movement is scaled by frame time", "[camera]") {
    // Three seconds of W at 1.5 m/s: 4.5 m along -z, whether the seconds come
    // as 60, 30 or 3 frames per second.
    const vkt::Input w = holding({'W'});
    for (int frames_per_second : {60, 30, 3}) {
        vkt::FpsCamera camera;
        for (int i = 0; i < 3 * frames_per_second; ++i)
            camera.update(w, 1.0f / float(frames_per_second), 1.5f, 0.002f);
        INFO(frames_per_second << " frames per second");
        check_vec(camera.position, {0, 0, -4.5f}, 1e-4f);
    }
    // Half the time, half the distance; no time, no distance; a negative dt
    // (a clock that went backwards) moves nothing.
    vkt::FpsCamera half, none, backwards;
    half.update(w, 0.25f, 2.0f, 0.002f);
    none.update(w, 0.0f, 2.0f, 0.002f);
    backwards.update(w, -1.0f, 2.0f, 0.002f);
    check_vec(half.position, {0, 0, -0.5f});
    check_vec(none.position, {0, 0, 0});
    check_vec(backwards.position, {0, 0, 0});
}

TEST_CASE("an empty input (headless) leaves the camera where it is", "[camera]") {
    vkt::FpsCamera camera = pose({1, 2, 3}, 20, -10);
    const vkt::FpsCamera before = camera;
    for (int i = 0; i < 100; ++i) camera.update(vkt::Input{}, 1.0f / 60, 5.0f, 0.002f);
    CHECK(camera.position == before.position);
    CHECK(camera.yaw == before.yaw);
    CHECK(camera.pitch == before.pitch);
}
