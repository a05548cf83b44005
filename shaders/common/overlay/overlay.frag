#version 450
// The overlay's pixels: the vertex colour times the font atlas (white glyphs
// whose alpha is their coverage; flat shapes sample its one white texel).
layout(set = 0, binding = 0) uniform sampler2D font;

layout(location = 0) in vec2 uv;
layout(location = 1) in vec4 colour;

layout(location = 0) out vec4 out_colour;

void main() {
    out_colour = colour * texture(font, uv);
}
