#pragma once
// Chapter 12's blocks as C++ structs, mirroring shaders/12_lighting/blocks.glsl:
// the std140 uniform block SceneUniforms and the std430 push constant block
// ObjectPush. tests/unit/test_lighting.cpp checks every offset here against
// the compiled SPIR-V.

#include "vkt/scene/lighting.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>

namespace ch12 {

constexpr uint32_t max_lights = 16;  // MAX_LIGHTS in the shader

// [scene-struct]
struct SceneUniforms {
    glm::mat4 view;                      // 0
    glm::mat4 proj;                      // 64
    glm::vec3 camera_position;           // 128
    int32_t light_count;                 // 140: fills camera_position's fourth word
    glm::vec3 ambient;                   // 144
    int32_t falloff;                     // 156: vkt::Falloff
    glm::vec3 classic;                   // 160: (constant, linear, quadratic)
    float specular;                      // 172
    float shininess;                     // 176
    float padding[3];                    // 180: an array of structs starts at a multiple of 16
    vkt::PointLight lights[max_lights];  // 192, 32 bytes each
};
static_assert(offsetof(SceneUniforms, camera_position) == 128);
static_assert(offsetof(SceneUniforms, light_count) == 140);
static_assert(offsetof(SceneUniforms, ambient) == 144 && offsetof(SceneUniforms, falloff) == 156);
static_assert(offsetof(SceneUniforms, classic) == 160 && offsetof(SceneUniforms, specular) == 172);
static_assert(offsetof(SceneUniforms, shininess) == 176 && offsetof(SceneUniforms, lights) == 192);
static_assert(sizeof(SceneUniforms) == 192 + 32 * max_lights);

// std430 mat3: three columns 16 bytes apart, so three vec4s in C++ (a glm::mat3
// packs its columns 12 bytes apart and would not match).
struct ObjectPush {
    glm::mat4 model;             // 0
    glm::vec4 normal_matrix[3];  // 64: columns, the fourth word unused
    glm::vec3 albedo;            // 112
    float emissive;              // 124: 1 for the lights' markers (unlit), else 0
};
static_assert(offsetof(ObjectPush, normal_matrix) == 64 && offsetof(ObjectPush, albedo) == 112);
static_assert(offsetof(ObjectPush, emissive) == 124);
static_assert(sizeof(ObjectPush) == 128);  // maxPushConstantsSize is at least 128
// [/scene-struct]

}  // namespace ch12
