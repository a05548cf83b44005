#pragma once
// Chapter 16's blocks as C++ structs, mirroring shaders/common/deferred/blocks.glsl,
// scene.vert and lighting.frag. tests/unit/test_deferred.cpp checks every
// offset here against the compiled SPIR-V.

#include "vkt/scene/lighting.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>

namespace vkt::deferred {

constexpr uint32_t max_materials = 8;  // MAX_MATERIALS in the shaders

// [structs]
struct Material {
    glm::vec3 albedo;  // 0: linear RGB
    float specular;    // 12: a multiple of 1/255, so the G-buffer stores it exactly
    float shininess;   // 16: a whole number 1..255, stored as shininess / 255
    float padding[3];  // 20: a std140 struct rounds up to 16 bytes
};
static_assert(sizeof(Material) == 32 && offsetof(Material, shininess) == 16);

struct FrameUniforms {
    glm::mat4 view;                     // 0
    glm::mat4 proj;                     // 64
    glm::mat4 inverse_view_proj;        // 128
    glm::vec3 camera_position;          // 192
    uint32_t light_count;               // 204
    glm::vec3 ambient;                  // 208
    float depth_view_far;               // 220
    Material materials[max_materials];  // 224
};
static_assert(offsetof(FrameUniforms, inverse_view_proj) == 128);
static_assert(offsetof(FrameUniforms, camera_position) == 192);
static_assert(offsetof(FrameUniforms, light_count) == 204);
static_assert(offsetof(FrameUniforms, ambient) == 208);
static_assert(offsetof(FrameUniforms, depth_view_far) == 220);
static_assert(offsetof(FrameUniforms, materials) == 224);

// std430 push constants of scene.vert: a mat3 is three columns 16 bytes apart.
struct ObjectPush {
    glm::mat4 model;             // 0
    glm::vec4 normal_matrix[3];  // 64
    uint32_t material;           // 112: index into FrameUniforms::materials
};
static_assert(offsetof(ObjectPush, material) == 112);
constexpr uint32_t object_push_size = 116;  // what the shader declares: 128 is the least offered

// lighting.frag's push constants.
enum View : int32_t { view_lit = 0, view_albedo, view_normal, view_material, view_depth };
struct LightingPush {
    int32_t view;          // 0
    uint32_t first_light;  // 4
    uint32_t light_count;  // 8
    float ambient;         // 12: 1, or 0 for the lights alone
};
static_assert(sizeof(LightingPush) == 16);
// [/structs]

}  // namespace vkt::deferred
