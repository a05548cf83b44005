#include "vkt/domains/physics_scene.hpp"

#include <algorithm>
#include <cmath>

namespace vkt::physics {

namespace {
// Sine and cosine from + and * alone, so that every platform gets the same
// bits. The C library's sinf and cosf need not round alike: MinGW-w64's and
// glibc's differ in the last bit for some arguments, and a heap of boxes
// turns one bit of a starting orientation into a different heap a few
// seconds later (the Windows build's chapter 14 picture differed). A Taylor
// series in double, for |x| <= pi after reduction, is good to about 1e-15,
// far inside float's rounding; + and * are exact IEEE operations everywhere.
constexpr double kPi = 3.14159265358979323846;

double series_sin(double x) {
    constexpr double pi = kPi, tau = 2.0 * kPi;
    while (x > pi) x -= tau;
    while (x < -pi) x += tau;
    const double x2 = x * x;
    double term = x, sum = x;
    for (int n = 1; n <= 13; ++n) {  // x^27 / 27! is below 1e-15 for |x| <= pi
        term *= -x2 / double((2 * n) * (2 * n + 1));
        sum += term;
    }
    return sum;
}

float portable_sin(float radians) {
    return float(series_sin(double(radians)));
}
float portable_cos(float radians) {
    return float(series_sin(double(radians) + 0.5 * kPi));
}
}  // namespace

glm::quat random_orientation(Random& random) {
    const float u1 = random(0.0f, 1.0f), u2 = random(0.0f, 1.0f), u3 = random(0.0f, 1.0f);
    const float a = std::sqrt(1.0f - u1), b = std::sqrt(u1);
    constexpr float tau = 6.28318530718f;
    return glm::quat(b * portable_cos(tau * u3), a * portable_sin(tau * u2),
                     a * portable_cos(tau * u2), b * portable_sin(tau * u3));
}

namespace {
// Boxes 1.6 m apart: boxes of at most 0.9 m along each axis reach at most
// 0.78 m from their centre however they are turned, so none starts inside
// another.
constexpr float kSpacing = 1.6f;
constexpr uint32_t kClusters = 4;
}  // namespace

// [scene]
Scene add_falling_boxes(World& world, uint32_t count, uint32_t seed) {
    Random random{seed * 2654435761u + 1u};
    // Each cluster is a loose heap in the air: square layers of boxes, two
    // each of side s, s - 1, ..., 1 from the bottom up, filled until the
    // cluster's share of the boxes is placed. s: the smallest that holds it.
    const uint32_t share = (count + kClusters - 1) / kClusters;
    uint32_t side = 1, room = 2;
    while (room < share) ++side, room += 2 * side * side;
    const float width = kSpacing * float(side);  // of one cluster's bottom layer
    const float offset = 0.6f * width;           // the clusters' centres: (+-offset, +-offset)
    Scene scene;
    scene.extent = offset + 0.5f * width;
    scene.floor_half_width = scene.extent + 8.0f;
    const float f = scene.floor_half_width;
    world.add_box({0.0f, -0.5f, 0.0f}, {f, 0.5f, f}, 0.0f);

    // The ramp: a slab turned about z, rising towards +x, its lower edge on
    // the floor, under the cluster at (+offset, -offset).
    const float angle = glm::radians(kRampDegrees);
    const glm::vec3 ramp_half(0.55f * width + 1.0f, 0.25f, 0.55f * width + 1.0f);
    const float sine = portable_sin(angle), cosine = portable_cos(angle);
    const glm::vec3 up(-sine, cosine, 0.0f);  // its top face's normal
    const glm::vec3 along(cosine, sine, 0.0f);
    // Turned by angle about z: the quaternion of half the angle.
    const glm::quat turn(portable_cos(0.5f * angle), 0.0f, 0.0f, portable_sin(0.5f * angle));
    const glm::vec3 low_edge(offset - 0.5f * width - 1.0f, 0.0f, -offset);
    scene.ramp =
        world.add_box(low_edge + ramp_half.x * along - ramp_half.y * up, ramp_half, 0.0f, turn);

    for (uint32_t cluster = 0; cluster < kClusters; ++cluster) {
        const glm::vec2 centre(cluster % 2 ? offset : -offset, cluster / 2 ? offset : -offset);
        const uint32_t first = cluster * share, last = std::min(count, first + share);
        uint32_t layer = 0, in_layer = 0;
        for (uint32_t i = first; i < last; ++i, ++in_layer) {
            if (in_layer == (side - layer / 2) * (side - layer / 2)) ++layer, in_layer = 0;
            const uint32_t m = side - layer / 2;                       // this layer is m x m
            const uint32_t column = in_layer % m, row = in_layer / m;  // whole numbers
            const float x = centre.x + (float(column) - 0.5f * float(m - 1)) * kSpacing;
            const float z = centre.y + (float(row) - 0.5f * float(m - 1)) * kSpacing;
            // Over the ramp, start above its surface there.
            const float ground =
                cluster == 1 ? std::max(0.0f, (x - low_edge.x) * (sine / cosine)) : 0.0f;
            const glm::vec3 half(random(0.15f, 0.45f), random(0.15f, 0.45f), random(0.15f, 0.45f));
            const float y = ground + 1.0f + float(layer) * kSpacing + random(0.0f, 0.05f);
            world.add_box({x, y, z}, half, 500.0f, random_orientation(random));
        }
    }
    return scene;
}
// [/scene]

void add_pyramid(World& world, glm::vec3 base, int levels, float half, float gap, float density) {
    for (int row = 0; row < levels; ++row) {
        const int n = levels - row;
        for (int i = 0; i < n; ++i) {
            const float x = base.x + (float(i) - 0.5f * float(n - 1)) * (2.0f * half + gap);
            world.add_box({x, half + 2.0f * half * float(row), base.z}, glm::vec3(half), density);
        }
    }
}

void add_tower(World& world, glm::vec3 base, int count, glm::vec3 half, float density) {
    for (int i = 0; i < count; ++i)
        world.add_box({base.x, half.y + 2.0f * half.y * float(i), base.z}, half, density);
}

void add_stacks(World& world, const Scene& scene) {
    // Behind the heaps and to their left, where nothing falls.
    const float f = scene.floor_half_width;
    add_pyramid(world, {0.0f, 0.0f, 4.0f - f}, 10, 0.3f, 0.02f);
    add_tower(world, {5.0f - f, 0.0f, 0.0f}, 20, glm::vec3(0.3f, 0.25f, 0.3f));
}

}  // namespace vkt::physics
