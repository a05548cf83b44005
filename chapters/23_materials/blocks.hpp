#pragma once
// Chapter 23's uniform block and push constants, as
// shaders/23_materials/blocks.glsl declares them (std140 and push constants:
// vec4s and a mat4 only, so the C++ layout is the GLSL one).

#include <glm/glm.hpp>

#include <cstdint>

struct FrameBlock {
    glm::mat4 clip_from_world;
    glm::mat4 world_from_clip;  // its inverse: the background's view rays
    glm::vec4 viewport;         // xy: the HDR target's size in pixels
    glm::vec4 eye;
    glm::vec4 light_direction[2];  // towards each light
    glm::vec4 light_radiance[2];
    glm::vec4 sky;  // rgb: the uniform sky's radiance, or the environment's scale; w: samples
};

struct DrawPush {
    glm::mat4 world_from_object;
    glm::vec4 base_colour;  // linear RGBA factor
    glm::vec4 factors;      // metallic, roughness, normal scale, occlusion strength
    glm::vec4 emissive;     // rgb: emissive factor; w: 1 where there is a normal map
};
static_assert(sizeof(DrawPush) == 112, "at most 128 bytes of push constants are promised");

struct TonemapPush {
    float exposure;     // a multiplier, 2^(--exposure)
    uint32_t tone_map;  // 0: ACES (Narkowicz's fit), 1: clamp
    float bloom;        // how much of the bloom is mixed in (--bloom)
    float levels;       // the bloom chain's levels
};

// The image-based light's compute steps' push constants (environment.hpp,
// shaders/23_materials/cube.glsl).
struct EnvironmentPush {
    glm::vec4 sun;      // xyz: towards the sun; w: 1 for the white furnace's sky
    float roughness;    // the specular level being made
    uint32_t samples;   // per texel
    float source_size;  // texels along a side of the sky's level 0
    float pad = 0.0f;
};
