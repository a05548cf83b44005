#version 450
// [vertex-shader]
// No vertex buffers yet (chapter 05): the three corners live in the shader
// and gl_VertexIndex (0, 1, 2) picks one. Positions are in Vulkan's clip
// space: x right, y down, both from -1 to 1.
const vec2 positions[3] = vec2[](vec2(0.0, -0.6), vec2(0.7, 0.6), vec2(-0.7, 0.6));
const vec3 colours[3] = vec3[](vec3(1.0, 0.1, 0.1), vec3(0.1, 1.0, 0.1), vec3(0.1, 0.2, 1.0));

layout(location = 0) out vec3 colour;

void main() {
    gl_Position = vec4(positions[gl_VertexIndex], 0.0, 1.0);
    colour = colours[gl_VertexIndex];
}
// [/vertex-shader]
