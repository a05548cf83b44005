#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's second pass: each pixel of the HDR target, exposed and tone
// mapped into 0..1, written to the _SRGB target (which encodes it).
#include "pbr.glsl"

layout(set = 0, binding = 0) uniform sampler2D hdr;

layout(push_constant) uniform Settings {
    float exposure;  // a multiplier: 2^stops
    uint tone_map;   // 0: ACES (Narkowicz's fit); 1: clamp
} settings;

layout(location = 0) out vec4 colour;

// [tonemap]
void main() {
    vec3 exposed = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb * settings.exposure;
    colour = vec4(settings.tone_map == 0u ? aces_narkowicz(exposed) : clamp(exposed, 0.0, 1.0), 1.0);
}
// [/tonemap]
