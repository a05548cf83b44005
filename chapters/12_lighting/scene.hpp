#pragma once
// Chapter 12's scene: its shapes, their objects and the lights, all functions
// of time, and the camera. In a header of its own so that
// tests/unit/test_lighting.cpp can shade a pixel of the very same scene on the
// CPU (the squashed sphere's, where the normal matrix is the lesson).

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/lighting.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace ch12 {

constexpr float pi = std::numbers::pi_v<float>;

enum Mesh { floor_mesh, cube_mesh, sphere_mesh, cylinder_mesh, torus_mesh, mesh_count };

struct Object {
    Mesh mesh;
    glm::mat4 model;
    glm::vec3 albedo;       // the fraction of each colour of light the surface scatters
    float emissive = 0.0f;  // 1: a light's marker, drawn in its colour, unlit
};

// x -> -x: the mirror image of a transform is M * model * M with M this
// reflection. Two reflections keep the winding, so back faces stay back faces.
inline glm::mat4 mirrored(const glm::mat4& model) {
    const glm::mat4 m = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
    return m * model * m;
}

// [objects]
// The shapes on the right (x > 0), each mirrored to the left, and in the
// middle a sphere squashed to an ellipsoid: the non-uniform scale that needs
// the normal matrix. Everything is a function of time t, for tests.
inline std::vector<Object> make_objects(float t) {
    const glm::vec3 up(0, 1, 0);
    std::vector<Object> right = {
        {sphere_mesh,
         vkt::transform({1.9f, 0.75f, 1.0f}, 0.0f, up, glm::vec3(1.5f)),
         {0.85f, 0.85f, 0.85f}},
        {cube_mesh,
         vkt::transform({3.6f, 0.5f, -1.0f}, 0.6f + 0.4f * t, up, glm::vec3(1.0f)),
         {0.9f, 0.55f, 0.35f}},
        {torus_mesh,
         vkt::transform({1.6f, 0.85f, -3.0f}, 0.5f * t, up, glm::vec3(1.7f)) *
             glm::rotate(glm::mat4(1.0f), pi / 2, glm::vec3(1, 0, 0)),
         {0.95f, 0.8f, 0.35f}},
        {cylinder_mesh,
         vkt::transform({3.6f, 0.6f, 2.2f}, 0.0f, up, {0.9f, 1.2f, 0.9f}),
         {0.4f, 0.65f, 0.9f}},
    };
    std::vector<Object> objects = {
        {floor_mesh, vkt::transform({0, 0, 0}, 0.0f, up, {12.0f, 1.0f, 12.0f}), {0.7f, 0.7f, 0.7f}},
        {sphere_mesh,
         vkt::transform({0, 0.45f, -1.2f}, 0.3f * t, up, {2.6f, 0.9f, 1.3f}),
         {0.55f, 0.85f, 0.5f}},
    };
    for (const Object& object : right) {
        objects.push_back(object);
        objects.push_back({object.mesh, mirrored(object.model), object.albedo});
    }
    return objects;
}
// [/objects]

// [lights]
// Light 0, warm white, swings over the middle of the floor (x = 0: its own
// mirror image). The others come in mirror pairs, each pair circling the
// right-hand shapes and their mirror images at its own speed and height. An
// odd count keeps the picture symmetric. The pairs fly at 1.6 and higher,
// above every shape, so that no light is ever inside one.
inline std::vector<vkt::PointLight> make_lights(uint32_t count, float t) {
    std::vector<vkt::PointLight> lights;
    lights.push_back({.position = {0.0f, 1.5f + 0.5f * std::sin(2.0f * t), -std::cos(0.8f * t)},
                      .radius = 6.0f,
                      .colour = {1.0f, 0.85f, 0.65f},
                      .intensity = 3.0f});
    const glm::vec3 palette[] = {{0.25f, 0.5f, 1.0f}, {1.0f, 0.3f, 0.45f}, {0.3f, 1.0f, 0.4f}};
    for (uint32_t pair = 1; lights.size() < count; ++pair) {
        const float k = float(pair);
        const float angle = 2.4f * k + (0.5f + 0.15f * k) * t;
        const float orbit = 2.0f + 0.4f * float(pair % 2);
        const float height = 1.75f + 0.15f * float(pair % 3) + 0.15f * std::sin(1.3f * t + k);
        // Beyond the palette: a cosine colour wheel, hues a golden ratio apart.
        const glm::vec3 wheel =
            0.5f + 0.5f * glm::cos(2.0f * pi * (0.618f * k + glm::vec3(0.0f, 1.0f, 2.0f) / 3.0f));
        const glm::vec3 colour = pair <= 3 ? palette[pair - 1] : wheel;
        vkt::PointLight light{
            .position = {2.6f + orbit * std::cos(angle), height, -0.4f + orbit * std::sin(angle)},
            .radius = 3.5f,
            .colour = colour,
            .intensity = 5.0f};
        lights.push_back(light);
        light.position.x = -light.position.x;  // its mirror image
        if (lights.size() < count) lights.push_back(light);
    }
    return lights;
}
// [/lights]

// Every shape in one vertex and one index buffer. The floor has few vertices
// and the spheres are coarse on purpose: that is where per vertex and per
// fragment lighting differ.
inline void build_meshes(vkt::shapes::MeshBuilder& builder,
                         vkt::shapes::MeshRange (&meshes)[mesh_count]) {
    meshes[floor_mesh] = builder.floor(4);
    meshes[cube_mesh] = builder.cube();
    meshes[sphere_mesh] = builder.sphere(10, 6);
    meshes[cylinder_mesh] = builder.cylinder(12);
    meshes[torus_mesh] = builder.torus(16, 8, 0.15f);
}

// The camera, high and in front, looks at the middle of the floor: the
// image centre shows the floor point (0, 0, 0).
inline const glm::vec3 eye(0.0f, 5.0f, 10.0f);

}  // namespace ch12
