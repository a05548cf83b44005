#pragma once
// Chapter 16's scene: materials, shapes, moving lights and the camera, each a
// function of time so that a frame's picture is reproducible. The shapes are chapter 12's
// (meshes.hpp).

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/deferred_blocks.hpp"
#include "vkt/scene/lighting.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace vkt::deferred {

constexpr float pi = std::numbers::pi_v<float>;

enum Mesh { floor_mesh, cube_mesh, sphere_mesh, cylinder_mesh, torus_mesh, mesh_count };

struct Object {
    Mesh mesh;
    glm::mat4 model;
    uint32_t material;
};

// A number the UNORM8 material target stores exactly: a multiple of 1/255.
inline float unorm8(float x) {
    return std::round(x * 255.0f) / 255.0f;
}

// [scene]
// Materials: albedo, specular strength, shininess (see blocks.glsl).
inline std::vector<Material> make_materials() {
    const struct {
        glm::vec3 albedo;
        float specular, shininess;
    } table[] = {
        {{0.7f, 0.7f, 0.7f}, 0.1f, 16},     // 0 floor
        {{0.85f, 0.85f, 0.85f}, 0.8f, 64},  // 1 white, shiny
        {{0.9f, 0.45f, 0.3f}, 0.2f, 8},     // 2 terracotta
        {{0.95f, 0.75f, 0.3f}, 0.9f, 128},  // 3 gold
        {{0.3f, 0.5f, 0.9f}, 0.5f, 32},     // 4 blue
        {{0.45f, 0.8f, 0.4f}, 0.3f, 16},    // 5 green
        {{0.9f, 0.5f, 0.7f}, 0.5f, 32},     // 6 pink
    };
    std::vector<Material> materials;
    for (const auto& m : table)
        materials.push_back({m.albedo, unorm8(m.specular), m.shininess, {}});
    return materials;
}

// Everything is a function of time t, so a frame's picture is reproducible.
inline std::vector<Object> make_objects(float t) {
    const glm::vec3 up(0, 1, 0);
    std::vector<Object> objects = {
        {floor_mesh, vkt::transform({0, 0, 0}, 0.0f, up, {12.0f, 1.0f, 12.0f}), 0},
        {sphere_mesh, vkt::transform({-2.4f, 0.9f, 0.4f}, 0.0f, up, glm::vec3(1.8f)), 1},
        {cube_mesh, vkt::transform({2.2f, 0.6f, 0.8f}, 0.6f + 0.4f * t, up, glm::vec3(1.2f)), 2},
        {torus_mesh,
         vkt::transform({0.0f, 1.0f, -2.2f}, 0.5f * t, up, glm::vec3(2.0f)) *
             glm::rotate(glm::mat4(1.0f), pi / 2, glm::vec3(1, 0, 0)),
         3},
        {cylinder_mesh, vkt::transform({-3.8f, 0.7f, -2.6f}, 0.0f, up, {1.0f, 1.4f, 1.0f}), 4},
        {sphere_mesh, vkt::transform({3.6f, 0.4f, -2.0f}, 0.3f * t, up, {2.4f, 0.8f, 1.2f}), 5},
    };
    for (int i = 0; i < 4; ++i)  // a row of small balls in front
        objects.push_back(
            {sphere_mesh, vkt::transform({-1.5f + float(i), 0.3f, 3.2f}, 0.0f, up, glm::vec3(0.6f)),
             6});
    return objects;
}

// N lights spread evenly over a disc of radius 5.5 in the middle of the
// floor (a sunflower spiral, a golden angle apart), each circling its own spot
// at its own speed and height. More lights get smaller radii: their circles
// share 4 x 144, four times the square floor's area, so that a point inside
// the disc (about 95 of those 144) lies under about 6 lights' circles (seen
// from above: the lights hang over the floor, so fewer of their spheres reach
// it) and the picture stays about as bright at any count; the floor's corners
// lie outside.
inline std::vector<vkt::PointLight> make_lights(uint32_t count, float t) {
    const float radius = std::min(6.0f, std::sqrt(4.0f * 144.0f / (pi * float(count))));
    std::vector<vkt::PointLight> lights(count);
    for (uint32_t i = 0; i < count; ++i) {
        const float k = float(i);
        // Two more sequences that spread evenly and do not follow the spiral.
        const float golden = std::fmod(0.618034f * k, 1.0f);
        const float hue = std::fmod(0.7548777f * k, 1.0f), level = std::fmod(0.5698403f * k, 1.0f);
        const float r = 5.5f * std::sqrt((k + 0.5f) / float(count));
        const float angle = 2.399963f * k;
        const float spin = (0.6f + 0.6f * golden) * (i % 2 ? 1.0f : -1.0f) * t + k;
        // Low enough to light the floor: a light higher than its radius would
        // not. Below 2,000 lights or so (radius 0.3 and more) the lowest are
        // 0.15 up; smaller lights hang at half their radius, so that 65,536
        // of them (radius 0.05) still light the floor.
        const float height = std::min(0.15f, 0.5f * radius) + level * std::min(1.5f, 0.6f * radius);
        const glm::vec3 home(r * std::cos(angle), height, r * std::sin(angle));
        lights[i] = {
            .position = home + 0.6f * glm::vec3(std::cos(spin), 0.0f, std::sin(spin)),
            .radius = radius,
            .colour = 0.5f + 0.5f * glm::cos(2.0f * pi * (hue + glm::vec3(0, 1, 2) / 3.0f)),
            .intensity = 0.4f * (1.0f + 0.25f * radius * radius),
        };
    }
    return lights;
}
// [/scene]

// [frame-uniforms]
// The camera looks at the middle of the floor from above and in front.
inline const glm::vec3 eye(0.0f, 6.0f, 10.0f);

// The frame's uniform block (blocks.glsl): the camera, the light count, the
// ambient light, the materials.
inline FrameUniforms frame_uniforms(float aspect, uint32_t light_count) {
    FrameUniforms frame{};
    frame.view = glm::lookAt(eye, glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
    frame.proj = vkt::vulkan_perspective(glm::radians(45.0f), aspect, 0.1f, 100.0f);
    frame.inverse_view_proj = glm::inverse(frame.proj * frame.view);
    frame.camera_position = eye;
    frame.light_count = light_count;
    frame.ambient = glm::vec3(0.03f);
    frame.depth_view_far = 20.0f;
    const std::vector<Material> materials = make_materials();
    std::copy(materials.begin(), materials.end(), frame.materials);
    return frame;
}
// [/frame-uniforms]

inline ObjectPush object_push(const Object& object) {
    const glm::mat3 normals = vkt::normal_matrix(object.model);
    ObjectPush push{};
    push.model = object.model;
    for (int column = 0; column < 3; ++column)
        push.normal_matrix[column] = glm::vec4(normals[column], 0.0f);
    push.material = object.material;
    return push;
}

}  // namespace vkt::deferred
