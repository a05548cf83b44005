#version 450
// Chapter 20: the transform pass's output read as an ordinary vertex buffer;
// the index buffer names each line's two vertices.
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 colour;  // R8G8B8A8_UNORM; alpha 0: behind the eye
layout(location = 0) out vec3 out_colour;
layout(location = 1) noperspective out float hidden;

void main() {
    gl_Position = vec4(position, 0.0, 1.0);
    out_colour = colour.rgb;
    hidden = 1.0 - colour.a;  // 0 at both ends of a visible line, exactly
}
