#version 450
// Chapter 29's last pass, on the graphics queue: the HDR image with the bloom
// mixed in, tone mapped by Reinhard's x / (1 + x) into the _SRGB target.
layout(set = 0, binding = 0) uniform sampler2D hdr;
layout(set = 0, binding = 1) uniform sampler2D bloom;  // level 0 of the bloom chain

layout(push_constant) uniform Settings {
    float bloom;   // how much of the bloom is mixed in: 0 (none) to 1
    float levels;  // the chain's levels, each of which added its blur
} settings;

layout(location = 0) out vec4 colour;

// [tonemap]
void main() {
    vec3 x = texelFetch(hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    if (settings.bloom > 0.0) {
        vec2 uv = gl_FragCoord.xy / vec2(textureSize(hdr, 0));
        x = mix(x, texture(bloom, uv).rgb / settings.levels, settings.bloom);
    }
    colour = vec4(x / (1.0 + x), 1.0);
}
// [/tonemap]
