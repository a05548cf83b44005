#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 16, pass 1: write what the lighting needs to know about the visible
// surface at each pixel into the G-buffer, and light nothing.
#include "blocks.glsl"
#include "normal_encoding.glsl"

// [gbuffer-frag]
layout(location = 0) in vec3 world_position;  // unused: depth gives it back
layout(location = 1) in vec3 world_normal;
layout(location = 2) flat in uint material;

layout(location = 0) out vec4 base_colour;  // R8G8B8A8_SRGB
layout(location = 1) out vec2 normal;       // R16G16_SNORM, octahedral
layout(location = 2) out vec4 params;       // R8G8B8A8_UNORM: specular, shininess / 255

void main() {
    Material m = frame.materials[material];
    base_colour = vec4(m.albedo, 1.0);  // linear in, the _SRGB format encodes it
    normal = oct_encode(normalize(world_normal));
    params = vec4(m.specular, m.shininess / 255.0, 0.0, 0.0);
}
// [/gbuffer-frag]
