#pragma once
// Chapter 23's default scenes, in numbers both the renderer and --verify
// read: the sphere grid (metallic down, roughness across) under two
// directional lights and a dim sky, and the white furnace (one white sphere,
// roughness 1, metallic 0, under a sky of radiance 1 and no lights).

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/gltf.hpp"
#include "vkt/scene/meshes.hpp"
#include "vkt/scene/pbr.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace grid {

constexpr int columns = 5, rows = 4;
constexpr float spacing = 1.1f, radius = 0.5f;
constexpr uint32_t sky_samples = 64;  // per lobe, for every pixel
constexpr glm::vec3 eye{0.0f, 0.0f, 8.0f};
constexpr float fov_y = 0.6981317f;  // 40 degrees

struct Sphere {
    glm::vec3 centre;
    float radius;
    vkt::pbr::Material material;
};

// [grid]
// Roughness 0.1 to 1 from left to right; metallic 0, 1/3, 2/3, 1 from top to
// bottom; one base colour, gold.
inline std::vector<Sphere> spheres(bool furnace) {
    if (furnace) return {{{0.0f, 0.0f, 0.0f}, 2.0f, {glm::vec3(1.0f), 0.0f, 1.0f}}};
    std::vector<Sphere> out;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column)
            out.push_back({{spacing * (float(column) - 0.5f * float(columns - 1)),
                            spacing * (0.5f * float(rows - 1) - float(row)), 0.0f},
                           radius,
                           {glm::vec3(1.0f, 0.71f, 0.29f), float(row) / float(rows - 1),
                            0.1f + 0.9f * float(column) / float(columns - 1)}});
    return out;
}
// [/grid]

// [lights]
// A warm key light from the upper left and a cool, dimmer fill from the
// right: directions towards the lights, and the irradiance each delivers to a
// surface facing it, in linear RGB.
inline std::array<vkt::pbr::Light, 2> lights(bool furnace) {
    if (furnace) return {{{{0, 0, 1}, glm::vec3(0.0f)}, {{0, 0, 1}, glm::vec3(0.0f)}}};
    return {{{glm::normalize(glm::vec3(-0.5f, 0.7f, 0.6f)), glm::vec3(4.0f, 3.8f, 3.4f)},
             {glm::normalize(glm::vec3(0.8f, -0.1f, 0.5f)), glm::vec3(0.5f, 0.6f, 0.9f)}}};
}
inline glm::vec3 sky(bool furnace) {
    return furnace ? glm::vec3(1.0f) : glm::vec3(0.05f, 0.06f, 0.09f);
}
// [/lights]

inline glm::mat4 clip_from_world(float aspect) {
    return vkt::vulkan_perspective(fov_y, aspect, 0.1f, 50.0f) *
           glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

struct Camera {
    glm::mat4 clip_from_world;
    glm::vec3 eye;
};
inline Camera camera(float aspect) {
    return {clip_from_world(aspect), eye};
}
// A glTF model's bounds, framed from in front, a little above and to the right.
inline Camera frame_model(const vkt::GltfScene& scene, float aspect) {
    const glm::vec3 centre = 0.5f * (scene.bounds_min + scene.bounds_max);
    const float size = std::max(0.5f * glm::length(scene.bounds_max - scene.bounds_min), 1e-4f);
    const float distance = size / std::sin(0.5f * fov_y * std::min(aspect, 1.0f));
    const glm::vec3 at = centre + distance * glm::normalize(glm::vec3(0.35f, 0.3f, 1.0f));
    return {vkt::vulkan_perspective(fov_y, aspect, 0.05f * size, distance + 2 * size) *
                glm::lookAt(at, centre, glm::vec3(0.0f, 1.0f, 0.0f)),
            at};
}

// The sphere grid (or the furnace's one sphere) as a glTF-like scene: one
// UV sphere of diameter 1, drawn once per sphere, scaled to its radius.
inline vkt::GltfScene sphere_scene(bool furnace) {
    vkt::shapes::MeshBuilder builder;
    const vkt::shapes::MeshRange sphere = builder.sphere(64, 32);
    vkt::GltfScene scene;
    for (const vkt::shapes::Vertex& v : builder.vertices)
        scene.vertices.push_back({v.position, v.normal, glm::vec2(0.0f), glm::vec4(0.0f)});
    scene.indices.assign(builder.indices.begin(), builder.indices.end());
    scene.primitives.push_back(
        {sphere.first_index, sphere.index_count, 0, uint32_t(scene.vertices.size()), 0});
    for (const grid::Sphere& s : spheres(furnace))
        scene.draws.push_back(
            {0, glm::scale(glm::translate(glm::mat4(1.0f), s.centre), glm::vec3(2.0f * s.radius))});
    return scene;
}

}  // namespace grid
