#pragma once
// Chapter 25's scene: the meshes of chapter 12's shapes, where each instance
// of them stands, and the record its closest-hit shader reads.

#include "vkt/resources/acceleration.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/meshes.hpp"

#include <vector>

namespace ch25 {

// One record per instance, read by the closest-hit shader (std430).
struct Object {
    glm::vec4 colour;
    uint32_t first_index;
    float reflectivity;
    uint32_t checker, unused;
};

// [scene]
// A checkered floor that reflects a little, a mirror ball, and three
// coloured shapes: every instance names its mesh and its Object record.
struct Scene {
    vkt::shapes::MeshBuilder meshes;
    std::vector<vkt::shapes::MeshRange> ranges;
    std::vector<vkt::MeshInstance> instances;
    std::vector<Object> objects;

    void add(uint32_t mesh, const glm::mat4& world, glm::vec3 colour, float reflectivity,
             bool checker = false) {
        instances.push_back(
            {.mesh = mesh, .world_from_object = world, .custom_index = uint32_t(objects.size())});
        objects.push_back(
            {glm::vec4(colour, 1), ranges[mesh].first_index, reflectivity, checker ? 1u : 0u, 0});
    }
};

Scene make_scene() {
    Scene s;
    s.ranges = {s.meshes.floor(1), s.meshes.sphere(48, 24), s.meshes.cube(),
                s.meshes.torus(48, 16, 0.25f)};
    enum { floor, sphere, cube, torus };
    s.add(floor, vkt::transform({0, 0, 0}, 0, {0, 1, 0}, {14, 1, 14}), {0.9f, 0.9f, 0.85f}, 0.2f,
          true);
    s.add(sphere, vkt::transform({0, 1, 0}, 0, {0, 1, 0}, glm::vec3(2)), {0.95f, 0.95f, 0.95f},
          0.85f);
    s.add(sphere, vkt::transform({-2.3f, 0.6f, 1.3f}, 0, {0, 1, 0}, glm::vec3(1.2f)),
          {0.85f, 0.25f, 0.2f}, 0.0f);
    s.add(cube, vkt::transform({2.3f, 0.6f, 0.9f}, 0.5f, {0, 1, 0}, glm::vec3(1.2f)),
          {0.25f, 0.4f, 0.9f}, 0.0f);
    s.add(torus, vkt::transform({0.4f, 0.3f, 2.6f}, 0.3f, {0, 1, 0}, glm::vec3(1.4f)),
          {0.3f, 0.8f, 0.35f}, 0.0f);
    return s;
}
// [/scene]

}  // namespace ch25
