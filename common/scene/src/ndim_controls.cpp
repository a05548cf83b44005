#include "vkt/scene/ndim_controls.hpp"

#include <algorithm>
#include <cstdio>

namespace vkt::ndim {

namespace {

// GLFW key codes for the controls (vkt/frame/input.hpp has the common ones).
constexpr int key_0 = 48, key_1 = 49, key_o = 79, key_r = 82, key_left_bracket = 91,
              key_right_bracket = 93, key_f1 = 290;

}  // namespace

Controls::Controls(int dimension, Projection start, const char* name)
    : n(dimension),
      projection(start),
      angles(size_t(plane_count(dimension)), 0.0f),
      offset(size_t(dimension), 0.0f),
      log_name(name) {}

void Controls::steer(const Input& input, float dt) {
    // One line on stderr per key that went down, when the chapter asked.
    const bool say = log_name != nullptr;
    const float sign = input.shift() ? -1.0f : 1.0f;
    const char* backwards = input.shift() ? " backwards" : "";
    const int planes = plane_count(n), pages = (planes + 9) / 10;
    if (input.went_down(key_right_bracket) || input.went_down(key_left_bracket)) {
        page = (page + (input.went_down(key_right_bracket) ? 1 : pages - 1)) % pages;
        const auto [i, j] = plane_axes(n, page * 10);
        if (say)
            std::fprintf(stderr, "%s: keys 1..0 turn planes %d.. from (%d,%d)\n", log_name,
                         page * 10 + 1, i, j);
    }
    for (int key = 0; key < 10; ++key) {
        const int plane = page * 10 + key, code = key == 9 ? key_0 : key_1 + key;
        if (plane >= planes || !input.down(code)) continue;
        angles[size_t(plane)] += sign * 1.0f * dt;  // 1 radian per second
        if (input.went_down(code)) {
            const auto [i, j] = plane_axes(n, plane);
            if (say)
                std::fprintf(stderr, "%s: turning in plane (%d,%d)%s\n", log_name, i, j, backwards);
        }
    }
    for (int axis = 0; axis < std::min(n, 12); ++axis) {
        if (!input.down(key_f1 + axis)) continue;
        offset[size_t(axis)] += sign * 1.5f * dt;  // 1.5 units per second
        if (say && input.went_down(key_f1 + axis))
            std::fprintf(stderr, "%s: moving along axis %d%s\n", log_name, axis, backwards);
    }
    if (input.went_down(key::space)) {
        paused = !paused;
        if (say) std::fprintf(stderr, "%s: spin %s\n", log_name, paused ? "paused" : "resumed");
    }
    if (input.went_down(key_o)) {
        const bool ortho = projection == Projection::perspective;
        projection = ortho ? Projection::orthographic : Projection::perspective;
        if (say)
            std::fprintf(stderr, "%s: %s projection\n", log_name,
                         ortho ? "orthographic" : "perspective");
    }
    if (input.went_down(key_r)) {
        const auto moved = [](const std::vector<float>& v) {
            return std::count_if(v.begin(), v.end(), [](float x) { return x != 0.0f; });
        };
        if (say)
            std::fprintf(stderr, "%s: reset %td turned planes and %td moved axes\n", log_name,
                         moved(angles), moved(offset));
        std::fill(angles.begin(), angles.end(), 0.0f);
        std::fill(offset.begin(), offset.end(), 0.0f);
    }
}

Transform Controls::pose(const SceneObject& object, float time) const {
    Transform t = object.at(time);
    for (size_t p = 0; p < t.angles.size(); ++p) t.angles[p] += angles[p];
    for (int k = 0; k < n; ++k) t.position[size_t(k)] += offset[size_t(k)];
    return t;
}

}  // namespace vkt::ndim
