// MovingLights: make_lights (deferred_scene.hpp), split at the time. The
// formulas are make_lights' own, in the same order, so every float but the
// phase comes out the same; test_tiles.cpp compares the two.

#include "vkt/scene/moving_lights.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

namespace vkt::deferred {

MovingLights::MovingLights(uint32_t count) : lights_(count), paths_(count) {
    constexpr float pi = std::numbers::pi_v<float>;
    const float radius = std::min(6.0f, std::sqrt(4.0f * 144.0f / (pi * float(count))));
    for (uint32_t i = 0; i < count; ++i) {
        const float k = float(i);
        const float golden = std::fmod(0.618034f * k, 1.0f);
        const float hue = std::fmod(0.7548777f * k, 1.0f), level = std::fmod(0.5698403f * k, 1.0f);
        const float r = 5.5f * std::sqrt((k + 0.5f) / float(count));
        const float angle = 2.399963f * k;
        // make_lights' spin is (0.6 + 0.6 golden) (+-1) t + k; k is reduced
        // modulo 2 pi in double precision, so the phase is exact to a float.
        const double phase = std::fmod(double(i), 2.0 * std::numbers::pi);
        paths_[i] = {(0.6f + 0.6f * golden) * (i % 2 ? 1.0f : -1.0f), float(phase)};
        const float height = std::min(0.15f, 0.5f * radius) + level * std::min(1.5f, 0.6f * radius);
        lights_[i] = {
            .position = glm::vec3(r * std::cos(angle), height, r * std::sin(angle)),
            .radius = radius,
            .colour = 0.5f + 0.5f * glm::cos(2.0f * pi * (hue + glm::vec3(0, 1, 2) / 3.0f)),
            .intensity = 0.4f * (1.0f + 0.25f * radius * radius),
        };
    }
}

void MovingLights::write(float t, vkt::PointLight* out) const {
    auto move = [&](uint32_t begin, uint32_t end) {
        for (uint32_t i = begin; i < end; ++i) {
            const float spin = paths_[i].speed * t + paths_[i].phase;
            vkt::PointLight light = lights_[i];
            light.position += path_radius * glm::vec3(std::cos(spin), 0.0f, std::sin(spin));
            out[i] = light;
        }
    };
    // A thread per core for large counts; below 65,536 lights one is enough
    // (about a millisecond), and starting threads would cost more than it saves.
    const uint32_t count = size();
    const uint32_t threads =
        count < 65536 ? 1 : std::clamp(std::thread::hardware_concurrency(), 1u, 64u);
    const uint32_t share = (count + threads - 1) / threads;
    std::vector<std::jthread> workers;  // each joins when it goes out of scope
    for (uint32_t begin = share; begin < count; begin += share)
        workers.emplace_back(move, begin, std::min(begin + share, count));
    move(0, std::min(share, count));
}

}  // namespace vkt::deferred
