#version 450
layout(location = 0) in vec3 world_normal;
layout(location = 1) in vec2 texcoord;
layout(location = 0) out vec4 target;

// [material]
// One descriptor set per material: its factor and its base colour texture
// (a 1x1 white one where the material has none).
layout(set = 0, binding = 0) uniform Material {
    vec4 base_color_factor;
} material;
layout(set = 0, binding = 1) uniform sampler2D base_color_texture;
// [/material]

void main() {
    vec4 base = texture(base_color_texture, texcoord) * material.base_color_factor;
    // [light]
    // Just enough light for shapes to read (chapter 12 does it properly): a
    // fixed sun, Lambert's cosine law, and some ambient so nothing is black.
    // A back face (no culling here) is lit from its own side.
    vec3 n = normalize(gl_FrontFacing ? world_normal : -world_normal);
    const vec3 to_sun = normalize(vec3(0.4, 1.0, 0.7));
    float light = 0.25 + 0.75 * max(dot(n, to_sun), 0.0);
    // [/light]
    target = vec4(base.rgb * light, 1.0);
}
