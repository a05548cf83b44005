#pragma once
// The keys of the n-dimensional chapters: taught in chapter 18, which writes
// them out in its main.cpp (book/18_ndim_cpu.md, "The keys"); chapters 19 and
// 20 steer their objects with this tidy form. What the user turned and moved
// is kept here and added to each object's own pose and spin.

#include "vkt/domains/ndim.hpp"
#include "vkt/frame/input.hpp"

#include <vector>

namespace vkt::ndim {

struct Controls {
    int n = 4;
    Projection projection = Projection::perspective;
    std::vector<float> angles, offset;  // added by the keys: per plane, per axis
    int page = 0;                       // which ten planes keys 1..0 turn
    bool paused = false;                // Space: the spin stops, the keys still turn
    // With a name, each key says what it did on stderr ("19_ndim_gpu:
    // turning in plane (0,1)"), as chapter 18's do; without one, silent.
    const char* log_name = nullptr;

    Controls(int dimension, Projection start, const char* name = nullptr);

    // Chapter 18's keys: 1..9, 0 turn the ten planes of the current page,
    // [ and ] change the page, F1..F12 move along axes 0..11, Shift
    // reverses, Space pauses the spin, O switches the projection, R resets.
    // Headless, input is always empty and the picture depends on the frame
    // index alone.
    void steer(const Input& input, float dt);

    // An object's pose at `time`: its start plus spin * time, plus the keys.
    Transform pose(const SceneObject& object, float time) const;
};

}  // namespace vkt::ndim
