#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's second pass: each pixel of the HDR target, exposed and tone
// mapped into 0..1, written to the _SRGB target (which encodes it).
#include "pbr.glsl"

layout(set = 0, binding = 0) uniform sampler2D hdr;
layout(set = 0, binding = 1) uniform sampler2D bloom;  // level 0 of the bloom chain (--bloom)

layout(push_constant) uniform Settings {
    float exposure;  // a multiplier: 2^stops
    uint tone_map;   // 0: ACES (Narkowicz's fit); 1: clamp
    float bloom;     // how much of the bloom is mixed in: 0 (none) to 1
    float levels;    // the bloom chain's levels, each of which added its blur
} settings;

layout(location = 0) out vec4 colour;

// [tonemap]
void main() {
    vec3 radiance = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    // [bloom-mix]
    if (settings.bloom > 0.0) {
        vec2 uv = gl_FragCoord.xy / vec2(textureSize(hdr, 0));
        radiance = mix(radiance, texture(bloom, uv).rgb / settings.levels, settings.bloom);
    }
    // [/bloom-mix]
    vec3 exposed = radiance * settings.exposure;
    colour = vec4(settings.tone_map == 0u ? aces_narkowicz(exposed) : clamp(exposed, 0.0, 1.0), 1.0);
}
// [/tonemap]
