#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 16, pass 2: for each pixel, read the G-buffer and light it; or,
// with --view, show one of the G-buffer's targets as it is.
#include "blocks.glsl"
#include "normal_encoding.glsl"

// [lighting-frag]
layout(set = 1, binding = 0) uniform sampler2D gbuffer_base_colour;
layout(set = 1, binding = 1) uniform sampler2D gbuffer_normal;
layout(set = 1, binding = 2) uniform sampler2D gbuffer_params;
layout(set = 1, binding = 3) uniform sampler2D gbuffer_depth;

const int VIEW_LIT = 0, VIEW_ALBEDO = 1, VIEW_NORMAL = 2, VIEW_MATERIAL = 3, VIEW_DEPTH = 4;

layout(push_constant, std430) uniform LightingPush {
    int view;          // VIEW_LIT, ...
    uint first_light;  // the lights [first_light, first_light + light_count)
    uint light_count;
    float ambient;     // 1, or 0 to sum the lights alone (the additivity test)
} pass;

layout(location = 0) out vec4 target;

const vec3 background = vec3(0.02, 0.02, 0.04);

// The debug views show a target's stored numbers as grey levels or colours.
// The target encodes what we write as sRGB, so decode first: the stored
// number v then reaches the screen as v.
vec3 as_stored(vec3 v) {
    return mix(v / 12.92, pow((v + 0.055) / 1.055, vec3(2.4)), greaterThan(v, vec3(0.04045)));
}

void main() {
    // Pixel centres: texelFetch reads one texel, no filtering, no sampler maths.
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(gbuffer_depth, pixel, 0).r;
    vec3 albedo = texelFetch(gbuffer_base_colour, pixel, 0).rgb;  // decoded to linear
    vec3 normal = oct_decode(texelFetch(gbuffer_normal, pixel, 0).rg);
    vec4 params = texelFetch(gbuffer_params, pixel, 0);

    // The world position from depth: undo the projection and the view.
    vec2 ndc = gl_FragCoord.xy / vec2(textureSize(gbuffer_depth, 0)) * 2.0 - 1.0;
    vec4 world = frame.inverse_view_proj * vec4(ndc, depth, 1.0);
    vec3 position = world.xyz / world.w;

    vec3 colour;
    if (pass.view == VIEW_ALBEDO) {
        colour = albedo;
    } else if (pass.view == VIEW_NORMAL) {
        colour = depth == 1.0 ? vec3(0.0) : as_stored(normal * 0.5 + 0.5);
    } else if (pass.view == VIEW_MATERIAL) {
        colour = as_stored(params.rgb);
    } else if (pass.view == VIEW_DEPTH) {
        float d = depth == 1.0 ? frame.depth_view_far : distance(position, frame.camera_position);
        colour = as_stored(vec3(1.0 - clamp(d / frame.depth_view_far, 0.0, 1.0)));
    } else if (depth == 1.0) {
        colour = background;  // nothing was drawn here: the forward pass's clear colour
    } else {
        Material m = Material(albedo, params.r, round(params.g * 255.0));
        colour = shade_all(position, normal, m, pass.first_light, pass.light_count, pass.ambient);
    }
    target = vec4(colour, 1.0);
}
// [/lighting-frag]
