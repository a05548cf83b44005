#version 460
#extension GL_GOOGLE_include_directive : require
// Chapter 26's fragments, for both pipelines: the model's colour, or each
// meshlet's own (--view meshlets), lit by one directional light; or, with
// --view culled, a meshlet the task shader would cull in its test's flat colour.

#include "meshlet_data.glsl"

layout(location = 0) in vec3 normal;
layout(location = 1) flat in uint meshlet;  // --view culled: the verdict
layout(location = 0) out vec4 colour;

// [meshlet-colour]
// A colour per meshlet from its index (an integer hash), bright enough to tell
// neighbours apart.
vec3 meshlet_colour(uint i) {
    i = (i ^ 61u) ^ (i >> 16);
    i *= 9u;
    i ^= i >> 4;
    i *= 0x27d4eb2du;
    i ^= i >> 15;
    return 0.25 + 0.75 * vec3(i & 0xFFu, (i >> 8) & 0xFFu, (i >> 16) & 0xFFu) / 255.0;
}
// [/meshlet-colour]

void main() {
    if (push.view == VIEW_CULLED && meshlet != KEPT) {
        colour = vec4(kCulledColour[meshlet], 1.0);
        return;
    }
    const vec3 light = normalize(vec3(0.4, 1.0, 0.6));
    const vec3 base = push.view == 1 ? meshlet_colour(meshlet) : push.base_colour.rgb;
    const float lambert = max(dot(normalize(normal), light), 0.0);
    colour = vec4(base * (0.2 + 0.8 * lambert), 1.0);
}
