#pragma once
// Chapter 19's keys, the same as chapter 18's (book/18_ndim_cpu.md, "The
// keys"): what the user turned and moved, on top of each object's spin.

#include "vkt/domains/ndim.hpp"
#include "vkt/frame/input.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace ch19 {

// GLFW key codes for the controls (vkt/frame/input.hpp has the common ones).
constexpr int key_0 = 48, key_1 = 49, key_o = 79, key_r = 82, key_left_bracket = 91,
              key_right_bracket = 93, key_f1 = 290;

struct Controls {
    int n = 4;
    vkt::ndim::Projection projection = vkt::ndim::Projection::perspective;
    std::vector<float> angles, offset;  // added by the keys: per plane, per axis
    int page = 0;
    bool paused = false;

    Controls(int dimension, vkt::ndim::Projection start)
        : n(dimension),
          projection(start),
          angles(size_t(vkt::ndim::plane_count(dimension)), 0.0f),
          offset(size_t(dimension), 0.0f) {}

    // Chapter 18's keys: 1..9, 0 turn the ten planes of the current page,
    // [ and ] change the page, F1..F12 move along axes 0..11, Shift
    // reverses, Space pauses the spin, O switches the projection, R resets.
    void steer(const vkt::Input& input, float dt) {
        const float sign = input.shift() ? -1.0f : 1.0f;
        const char* backwards = input.shift() ? " backwards" : "";
        const int planes = vkt::ndim::plane_count(n), pages = (planes + 9) / 10;
        if (input.went_down(key_right_bracket) || input.went_down(key_left_bracket)) {
            page = (page + (input.went_down(key_right_bracket) ? 1 : pages - 1)) % pages;
            const auto [i, j] = vkt::ndim::plane_axes(n, page * 10);
            std::fprintf(stderr, "19_ndim_gpu: keys 1..0 turn planes %d.. from (%d,%d)\n",
                         page * 10 + 1, i, j);
        }
        for (int key = 0; key < 10; ++key) {
            const int plane = page * 10 + key, code = key == 9 ? key_0 : key_1 + key;
            if (plane >= planes || !input.down(code)) continue;
            angles[size_t(plane)] += sign * 1.0f * dt;  // 1 radian per second
            if (input.went_down(code)) {
                const auto [i, j] = vkt::ndim::plane_axes(n, plane);
                std::fprintf(stderr, "19_ndim_gpu: turning in plane (%d,%d)%s\n", i, j, backwards);
            }
        }
        for (int axis = 0; axis < std::min(n, 12); ++axis) {
            if (!input.down(key_f1 + axis)) continue;
            offset[size_t(axis)] += sign * 1.5f * dt;  // 1.5 units per second
            if (input.went_down(key_f1 + axis))
                std::fprintf(stderr, "19_ndim_gpu: moving along axis %d%s\n", axis, backwards);
        }
        if (input.went_down(vkt::key::space)) {
            paused = !paused;
            std::fprintf(stderr, "19_ndim_gpu: spin %s\n", paused ? "paused" : "resumed");
        }
        if (input.went_down(key_o)) {
            const bool ortho = projection == vkt::ndim::Projection::perspective;
            projection =
                ortho ? vkt::ndim::Projection::orthographic : vkt::ndim::Projection::perspective;
            std::fprintf(stderr, "19_ndim_gpu: %s projection\n",
                         ortho ? "orthographic" : "perspective");
        }
        if (input.went_down(key_r)) {
            const auto moved = [](const std::vector<float>& v) {
                return std::count_if(v.begin(), v.end(), [](float x) { return x != 0.0f; });
            };
            std::fprintf(stderr, "19_ndim_gpu: reset %td turned planes and %td moved axes\n",
                         moved(angles), moved(offset));
            std::fill(angles.begin(), angles.end(), 0.0f);
            std::fill(offset.begin(), offset.end(), 0.0f);
        }
    }
};

}  // namespace ch19
