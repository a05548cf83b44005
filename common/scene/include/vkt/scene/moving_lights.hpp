#pragma once
// Chapter 16's lights (make_lights in deferred_scene.hpp), made fast enough
// for chapter 17's million. make_lights works out every light from scratch
// each frame: eight sines and cosines a light, half a second for 1,048,576 of
// them on one core. Most of it does not change with time (each light's home
// spot, speed, radius, colour and intensity), so MovingLights works that out
// once; a frame then computes only where each light is on its circle, on
// every CPU core, straight into the buffer the GPU reads. The lights are
// make_lights', bit for bit (tests/unit/test_tiles.cpp checks it).

#include "vkt/scene/lighting.hpp"

#include <cstdint>
#include <vector>

namespace vkt::deferred {

class MovingLights {
public:
    explicit MovingLights(uint32_t count);

    uint32_t size() const { return uint32_t(lights_.size()); }
    // The lights at time t, into out[0 .. size()): make_lights(size(), t).
    void write(float t, vkt::PointLight* out) const;

private:
    struct Circling {
        float speed, phase;  // the angle on its circle at time t: speed * t + phase
    };
    std::vector<vkt::PointLight> lights_;  // position: the centre of its circle
    std::vector<Circling> circling_;
};

}  // namespace vkt::deferred
