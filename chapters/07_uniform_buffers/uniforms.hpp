#pragma once
// Chapter 07's uniform blocks as C++ structs. They must match the GLSL blocks
// in shaders/07_uniform_buffers/cube.vert byte for byte: std140 puts a mat4 on
// a 16-byte boundary (four vec4 columns), a vec3 on a 16-byte boundary too,
// and lets a float fill the 4 bytes after a vec3. The static_asserts check the
// offsets here; tests/unit/test_std140.cpp checks them against the compiled
// SPIR-V.

#include <glm/glm.hpp>

#include <cstddef>

namespace ch07 {

// [uniform-structs]
// Binding 0: written once per frame, read by every draw.
struct FrameUniforms {
    glm::mat4 view;  // offset 0: world -> camera
    glm::mat4 proj;  // offset 64: camera -> clip
};
static_assert(offsetof(FrameUniforms, view) == 0);
static_assert(offsetof(FrameUniforms, proj) == 64);
static_assert(sizeof(FrameUniforms) == 128);

// Binding 1 (dynamic): one of these per object, each at its own aligned offset.
struct ObjectUniforms {
    glm::mat4 world;    // offset 0: object -> world
    glm::vec3 tint;     // offset 64: std140 aligns a vec3 like a vec4...
    float tint_amount;  // offset 76: ...and a float may use its last 4 bytes
};
static_assert(offsetof(ObjectUniforms, world) == 0);
static_assert(offsetof(ObjectUniforms, tint) == 64);
static_assert(offsetof(ObjectUniforms, tint_amount) == 76);
static_assert(sizeof(ObjectUniforms) == 80);
// [/uniform-structs]

}  // namespace ch07
