#version 450
// [uniform-blocks]
// Set 0 holds two uniform buffers. Binding 0: the camera, the same for every
// draw of a frame. Binding 1: one object's transform and tint; it is a
// dynamic uniform buffer, so each draw picks its object with an offset given
// to vkCmdBindDescriptorSets. std140 is the layout rule for uniform blocks;
// chapters/07_uniform_buffers/uniforms.hpp mirrors both blocks in C++.
layout(set = 0, binding = 0, std140) uniform FrameUniforms {
    mat4 view;
    mat4 proj;
} frame;

layout(set = 0, binding = 1, std140) uniform ObjectUniforms {
    mat4 world;
    vec3 tint;
    float tint_amount;
} object;
// [/uniform-blocks]

layout(location = 0) in vec3 position;  // a cube of edge 1 around (0, 0, 0)
layout(location = 1) in vec3 colour;    // the face's colour

layout(location = 0) out vec3 out_colour;

void main() {
    // [transform]
    // Object -> world -> camera -> clip, read right to left.
    gl_Position = frame.proj * frame.view * object.world * vec4(position, 1.0);
    // [/transform]
    out_colour = mix(colour, object.tint, object.tint_amount);
}
