#pragma once
// Chapter 16's lights (make_lights in deferred_scene.hpp), made fast enough
// for chapter 17's million. make_lights works out every light from scratch
// each frame: seven sines and cosines a light, half a second for 1,048,576 of
// them on one core. Most of it does not change with time (each light's home
// spot, speed, radius, colour and intensity), so MovingLights works that out
// once (its home and its path); a frame then computes only where each light
// is on its circle. Chapter 17 uploads the homes and paths once and moves the
// lights on the GPU (light_motion.hpp); write() is the same step on the CPU,
// on every core, the reference its --verify compares the GPU's with.
//
// Each path's phase is make_lights' k reduced modulo 2 pi: the same circle
// and the same motion, but the angle stays small, where a GPU's sine and
// cosine are accurate (at k near a million, k itself in a float is only
// good to 1/16 of a radian). The positions differ from make_lights' by that
// rounding alone (tests/unit/test_tiles.cpp bounds it); the rest is bit for bit.

#include "vkt/scene/lighting.hpp"

#include <cstdint>
#include <vector>

namespace vkt::deferred {

class MovingLights {
public:
    // [path]
    // A light's path: a circle of radius 0.6 round its home, the angle at
    // time t being speed * t + phase (the GPU's Path in move_lights.comp).
    struct Path {
        float speed, phase;
    };
    // The light at time t: its home moved `path_radius` along the angle.
    static constexpr float path_radius = 0.6f;
    // [/path]

    explicit MovingLights(uint32_t count);

    uint32_t size() const { return uint32_t(lights_.size()); }
    // Every light at its circle's centre, and every light's path.
    const std::vector<vkt::PointLight>& homes() const { return lights_; }
    const std::vector<Path>& paths() const { return paths_; }
    // The lights at time t, into out[0 .. size()).
    void write(float t, vkt::PointLight* out) const;

private:
    std::vector<vkt::PointLight> lights_;  // position: the centre of its circle
    std::vector<Path> paths_;
};

}  // namespace vkt::deferred
