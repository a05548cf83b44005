#pragma once
// Chapter 22's uniform block, as scene.vert and scene.frag declare it
// (set 0, binding 0, std140: every member 16-byte aligned, so the C++ layout
// is the same; tests/unit/test_cascades.cpp checks it against the SPIR-V).

#include <glm/glm.hpp>

struct FrameBlock {
    glm::mat4 clip_from_world;
    glm::mat4 light_from_world[4];  // one per cascade
    glm::vec4 splits;               // the far distance of each cascade
    glm::vec4 eye, forward, light;  // xyz: the camera's position and view, the light's direction
    glm::uvec4 settings;            // x: cascades, y: 1 to colour them
};
