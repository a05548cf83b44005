#pragma once
// Chapter 22's scene: what main.cpp draws and casts shadows from, in a header
// of its own so that tests/unit/test_cascades.cpp can cast rays through the
// very same boxes.

#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/glm.hpp>

#include <vector>

struct Draw {
    glm::mat4 world_from_object;
    glm::vec4 colour;
    vkt::shapes::MeshRange mesh;
};

// [scene]
// A floor 60 units deep, two rows of pillars walking away from the camera,
// a sphere and a torus near it: shadows from a few units to fifty away.
inline std::vector<Draw> make_scene(vkt::shapes::MeshBuilder& meshes) {
    const vkt::shapes::MeshRange floor = meshes.floor(1), cube = meshes.cube(),
                                 sphere = meshes.sphere(32, 16),
                                 torus = meshes.torus(48, 16, 0.25f);
    std::vector<Draw> draws;
    draws.push_back(
        {vkt::transform({0, 0, -22}, 0, {0, 1, 0}, {40, 1, 60}), {0.8f, 0.8f, 0.75f, 1}, floor});
    for (int i = 0; i < 8; ++i)
        for (float x : {-3.0f, 3.0f})
            draws.push_back({vkt::transform({x, 1.5f, 2.0f - 7.0f * float(i)}, 0.3f * float(i),
                                            {0, 1, 0}, {0.6f, 3.0f, 0.6f}),
                             {0.85f, 0.45f, 0.3f, 1},
                             cube});
    draws.push_back({vkt::transform({-0.8f, 0.7f, 3.0f}, 0, {0, 1, 0}, glm::vec3(1.4f)),
                     {0.3f, 0.55f, 0.9f, 1},
                     sphere});
    draws.push_back({vkt::transform({1.2f, 0.9f, 1.0f}, 0.6f, {1, 0, 0}, glm::vec3(1.6f)),
                     {0.35f, 0.8f, 0.45f, 1},
                     torus});
    return draws;
}
// [/scene]

// The sun: the direction its light travels, down and away from the camera.
inline glm::vec3 light_direction() {
    return glm::normalize(glm::vec3(-0.6f, -1.0f, -0.45f));
}
