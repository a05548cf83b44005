// Chapter 12's two blocks, shared by lit.vert and lit.frag. Their C++ mirrors
// are in chapters/12_lighting/blocks.hpp; tests/unit/test_lighting.cpp checks
// every offset against the compiled SPIR-V.
#include "lighting.glsl"

// [scene-block]
const int MAX_LIGHTS = 16;

// Written once per frame. std140: a vec3 is 16-byte aligned and a scalar may
// fill its fourth word; an array of structs starts at a multiple of 16.
layout(set = 0, binding = 0, std140) uniform SceneUniforms {
    mat4 view;             // 0
    mat4 proj;             // 64
    vec3 camera_position;  // 128
    int light_count;       // 140
    vec3 ambient;          // 144
    int falloff;           // 156: FALLOFF_CLASSIC or FALLOFF_WINDOWED
    vec3 classic;          // 160: (constant, linear, quadratic)
    float specular;        // 172
    float shininess;       // 176, then 12 bytes of padding
    PointLight lights[MAX_LIGHTS];  // 192, 32 bytes apart
} scene;

// Per draw. Push constants are std430: a mat3 is three vec3 columns, each
// padded to 16 bytes. 128 bytes in all, the least every device offers.
layout(push_constant, std430) uniform ObjectPush {
    mat4 model;          // 0: object -> world
    mat3 normal_matrix;  // 64: inverse transpose of model's upper 3x3
    vec3 albedo;         // 112
    float emissive;      // 124: 1 for the lights' markers
} object;
// [/scene-block]

// [shade]
// Ambient plus every light, the same sum as vkt::shade on the CPU.
vec3 shade(vec3 position, vec3 normal, vec3 albedo) {
    vec3 n = normalize(normal);
    vec3 v = normalize(scene.camera_position - position);
    vec3 colour = scene.ambient * albedo;
    for (int i = 0; i < scene.light_count; ++i)
        colour += shade_point_light(position, n, v, albedo, scene.lights[i], scene.falloff,
                                    scene.classic, scene.specular, scene.shininess);
    return colour;
}
// [/shade]

// The small spheres that mark the lights glow in their own colour, unlit.
vec3 surface_colour(vec3 position, vec3 normal) {
    return object.emissive != 0.0 ? object.albedo : shade(position, normal, object.albedo);
}
