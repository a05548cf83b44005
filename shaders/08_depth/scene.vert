#version 450
// Chapter 07's shader: the camera in binding 0, one object's transform and
// tint in the dynamic binding 1.
layout(set = 0, binding = 0, std140) uniform FrameUniforms {
    mat4 view;
    mat4 proj;
} frame;

layout(set = 0, binding = 1, std140) uniform ObjectUniforms {
    mat4 world;
    vec3 tint;
    float tint_amount;
} object;

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 colour;

layout(location = 0) out vec3 out_colour;

void main() {
    // The depth test uses gl_Position.z / gl_Position.w, which the projection
    // makes 0 at the near plane and 1 at the far plane.
    gl_Position = frame.proj * frame.view * object.world * vec4(position, 1.0);
    out_colour = mix(colour, object.tint, object.tint_amount);
}
