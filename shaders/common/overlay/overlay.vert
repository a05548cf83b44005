#version 450
// The overlay's vertices (common/frame/src/overlay.cpp, chapter 21): Dear
// ImGui's triangles in window pixels, mapped to clip space by the push
// constants. Its colours are sRGB-encoded bytes meant for a _UNORM target;
// ours is _SRGB and encodes what the fragment shader writes, so they are
// decoded here, once per vertex.
layout(push_constant) uniform Push {
    vec2 scale;
    vec2 translate;
} push;

layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;  // R8G8B8A8_UNORM: 0..1, sRGB-encoded

layout(location = 0) out vec2 out_uv;
layout(location = 1) out vec4 out_colour;

// [overlay-srgb]
vec3 srgb_to_linear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c));
}

void main() {
    out_uv = uv;
    out_colour = vec4(srgb_to_linear(colour.rgb), colour.a);
    gl_Position = vec4(position * push.scale + push.translate, 0.0, 1.0);
}
// [/overlay-srgb]
