#version 450
// [pass-through]
// The CPU did all the work: the point arrives in clip space already, n
// dimensions transformed and projected down to 2. The shader only places it.
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 colour;  // R8G8B8A8_UNORM: 0..255 read as 0..1
layout(location = 0) out vec3 out_colour;

void main() {
    gl_Position = vec4(position, 0.0, 1.0);
    out_colour = colour.rgb;
}
// [/pass-through]
