#version 450
#extension GL_GOOGLE_include_directive : require
// Chapter 23's background under the environment: behind the spheres, the
// sky itself, seen along each pixel's view ray (drawn first, with the
// full-screen triangle of chapter 16, neither testing nor writing depth).
#include "blocks.glsl"

layout(set = 2, binding = 0) uniform samplerCube sky_map;

layout(location = 0) out vec4 radiance;

// [background]
void main() {
    vec2 ndc = gl_FragCoord.xy / frame.viewport.xy * 2.0 - 1.0;
    vec4 far = frame.world_from_clip * vec4(ndc, 1.0, 1.0);
    vec3 ray = normalize(far.xyz / far.w - frame.eye.xyz);
    radiance = vec4(frame.sky.rgb * textureLod(sky_map, ray, 0.0).rgb, 1.0);
}
// [/background]
