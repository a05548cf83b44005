// Chapter 23's uniform block and push constants (chapters/23_materials/blocks.hpp).
layout(set = 0, binding = 0) uniform Frame {
    mat4 clip_from_world;
    mat4 world_from_clip;   // its inverse: the background's view rays
    vec4 viewport;          // xy: the HDR target's size in pixels
    vec4 eye;               // xyz: the camera
    vec4 light_direction[2];  // xyz: towards each light
    vec4 light_radiance[2];   // rgb
    vec4 sky;               // rgb: the uniform sky's radiance, or the environment's scale; w: samples per lobe
} frame;

layout(push_constant) uniform Draw {
    mat4 world_from_object;
    vec4 base_colour;  // linear RGBA factor
    vec4 factors;      // metallic, roughness, normal scale, occlusion strength
    vec4 emissive;     // rgb: emissive factor; w: 1 where the material has a normal map
} draw;
