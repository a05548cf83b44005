#pragma once
// Chapter 08's uniform blocks as C++ structs, matching the std140 blocks of
// shaders/08_depth/scene.vert (the same two blocks as chapter 07's: see
// chapters/07_uniform_buffers/uniforms.hpp for the rules).
// tests/unit/test_std140.cpp checks them against the compiled SPIR-V.

#include <glm/glm.hpp>

#include <cstddef>

namespace ch08 {

struct FrameUniforms {
    glm::mat4 view;  // offset 0: world -> camera
    glm::mat4 proj;  // offset 64: camera -> clip, vkt::vulkan_perspective
};
static_assert(offsetof(FrameUniforms, proj) == 64 && sizeof(FrameUniforms) == 128);

struct ObjectUniforms {
    glm::mat4 world;    // offset 0: object -> world, T * R * S
    glm::vec3 tint;     // offset 64
    float tint_amount;  // offset 76
};
static_assert(offsetof(ObjectUniforms, tint) == 64 && offsetof(ObjectUniforms, tint_amount) == 76);
static_assert(sizeof(ObjectUniforms) == 80);

}  // namespace ch08
