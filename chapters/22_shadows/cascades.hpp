#pragma once
// Chapter 22's cascades: where the camera's view is split, and the light's
// orthographic projection fitted around each slice. Pure functions of the
// camera and the light, so tests/unit/test_cascades.cpp can check them.

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

struct Camera {
    glm::vec3 eye, forward, up;  // forward and up: unit length, perpendicular
    float fov_y, aspect, z_near, z_far;
};

// [splits]
// The practical split scheme: each boundary between n and f is a blend of
// the logarithmic split n (f/n)^(i/N), which keeps a shadow texel the same
// size on screen at every distance, and the uniform split n + (f - n) i/N,
// which would spend too few texels near the camera. lambda = 1 is all
// logarithmic. Returns N + 1 distances from n to f.
inline std::vector<float> cascade_splits(float n, float f, uint32_t count, float lambda) {
    std::vector<float> splits(count + 1);
    for (uint32_t i = 0; i <= count; ++i) {
        const float t = float(i) / float(count);
        splits[i] = lambda * n * std::pow(f / n, t) + (1.0f - lambda) * (n + (f - n) * t);
    }
    return splits;
}
// [/splits]

// The eight corners of the camera's view between distances d0 and d1.
inline std::array<glm::vec3, 8> slice_corners(const Camera& c, float d0, float d1) {
    const glm::vec3 right = glm::normalize(glm::cross(c.forward, c.up));
    std::array<glm::vec3, 8> corners;
    int k = 0;
    for (float d : {d0, d1}) {
        const float h = d * std::tan(c.fov_y / 2.0f), w = h * c.aspect;
        for (float sy : {-1.0f, 1.0f})
            for (float sx : {-1.0f, 1.0f})
                corners[k++] = c.eye + d * c.forward + sx * w * right + sy * h * c.up;
    }
    return corners;
}

// [snap]
// Moves the box's centre, in the light's axes (x and y across the map), to
// the nearest corner of the map's texel grid. That grid is then fixed in the
// world: as the camera moves, the box moves by whole texels only, and every
// point of the scene stays at the same place inside its texel.
inline glm::vec3 snap_to_texels(glm::vec3 centre, float texel) {
    return {std::round(centre.x / texel) * texel, std::round(centre.y / texel) * texel, centre.z};
}
// [/snap]

// [light-from-world]
// The light's view of one slice: an orthographic box around the slice's
// bounding sphere (so it does not change size as the camera turns), looking
// along the light, reaching `behind` further back towards the light so that
// casters between the light and the slice still land in the map, its centre
// snapped to the texels of a map `map_size` texels wide. Vulkan's clip
// space: x and y from -1 to 1, depth 0 (towards the light) to 1.
inline glm::mat4 light_from_world(const std::array<glm::vec3, 8>& corners, glm::vec3 light_dir,
                                  float behind, uint32_t map_size) {
    // The sphere around the slice's corners.
    glm::vec3 centre(0.0f);
    for (const glm::vec3& p : corners) centre += p / 8.0f;
    float radius = 0.0f;
    for (const glm::vec3& p : corners) radius = std::max(radius, glm::length(p - centre));
    // The light's axes, with no translation: x and y across the map, z back
    // towards the light.
    const glm::vec3 up = std::abs(light_dir.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::mat4 axes = glm::lookAt(glm::vec3(0.0f), light_dir, up);
    // 22b: snap to whole texels (the next two statements).
    // [fit-snap]
    // Half the box's side: the sphere and half a texel more each way, so the
    // snap (at most half a texel) leaves the slice inside the map.
    const float half = radius * float(map_size) / float(map_size - 1);
    const glm::vec3 c =
        snap_to_texels(glm::vec3(axes * glm::vec4(centre, 1.0f)), 2.0f * half / float(map_size));
    // [/fit-snap]
    // The box's near face, towards the light, is radius + behind from c.
    const glm::mat4 view =
        glm::translate(glm::mat4(1.0f), -glm::vec3(c.x, c.y, c.z + radius + behind)) * axes;
    const float depth = 2.0f * radius + behind;  // from the near face to the far side of the sphere
    glm::mat4 ortho(1.0f);
    ortho[0][0] = 1.0f / half;
    ortho[1][1] = 1.0f / half;
    ortho[2][2] = -1.0f / depth;  // view space looks down -z
    return ortho * view;
}
// [/light-from-world]
