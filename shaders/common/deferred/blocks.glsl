// Chapter 16's blocks, shared by every shader of the chapter. Their C++
// mirrors are in common/scene/include/vkt/scene/deferred_blocks.hpp; tests/unit/test_deferred.cpp
// checks every offset against the compiled SPIR-V.
#include "lighting.glsl"

// [blocks]
const int MAX_MATERIALS = 8;

// A surface's parameters: what the G-buffer's base colour and material
// targets hold for each pixel. std140: 32 bytes, a struct rounds up to 16.
struct Material {
    vec3 albedo;      // 0: linear RGB
    float specular;   // 12: strength of the white highlight, a multiple of 1/255
    float shininess;  // 16: Blinn-Phong exponent, a whole number 1..255
};

// Written once per frame (set 0, binding 0), read by every pass.
layout(set = 0, binding = 0, std140) uniform FrameUniforms {
    mat4 view;               // 0
    mat4 proj;               // 64
    mat4 inverse_view_proj;  // 128: clip space -> world, for positions from depth
    vec3 camera_position;    // 192
    uint light_count;        // 204: lights[0 .. light_count) below
    vec3 ambient;            // 208
    float depth_view_far;    // 220: distance shown black in the depth view
    Material materials[MAX_MATERIALS];  // 224, 32 bytes apart
} frame;

// The lights, as many as --lights says (up to 65,536): std430, 32 bytes each
// (set 0, binding 1), rewritten every frame as they move.
layout(set = 0, binding = 1, std430) readonly buffer Lights {
    PointLight lights[];
};
// [/blocks]

// [shade-all]
// Ambient plus the lights [first, first + count), each with the windowed
// falloff: the sum vkt::shade makes on the CPU, in the same order. A light
// whose radius does not reach the point adds exactly zero, so it is skipped.
vec3 shade_all(vec3 position, vec3 normal, Material m, uint first, uint count, float ambient) {
    vec3 n = normalize(normal);
    vec3 v = normalize(frame.camera_position - position);
    vec3 colour = ambient * frame.ambient * m.albedo;
    for (uint i = first; i < first + count; ++i) {
        PointLight light = lights[i];
        if (distance(light.position, position) >= light.radius) continue;
        colour += shade_point_light(position, n, v, m.albedo, light, FALLOFF_WINDOWED,
                                    vec3(1.0, 0.0, 0.0), m.specular, m.shininess);
    }
    return colour;
}
// [/shade-all]
