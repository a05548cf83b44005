#version 450
// Chapter 09: the floor's colour is the texture, sampled.

// [floor-fragment]
// A combined image sampler: the image view and the sampler in one binding.
layout(set = 0, binding = 0) uniform sampler2D floor_texture;

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 colour;

void main() {
    // texture() filters: it picks the mip level from how fast uv changes
    // between neighbouring pixels, and blends texels (and levels) linearly.
    // The _SRGB image is decoded to linear values as it is sampled.
    colour = texture(floor_texture, uv);
}
// [/floor-fragment]
