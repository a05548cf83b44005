#version 450
// [instance-inputs]
// Per vertex (binding 0, advancing every vertex): a corner of the unit cube
// (-1..1) and its face's normal.
layout(location = 0) in vec3 corner;
layout(location = 1) in vec3 normal;
// Per instance (binding 1, advancing once per box): where the box is, how
// big, what colour. The same 24 corners are drawn once for every box.
layout(location = 2) in vec3 box_position;
layout(location = 3) in vec3 box_half_extents;
layout(location = 4) in vec4 box_colour;  // R8G8B8A8_UNORM: 0..255 read as 0..1
// [/instance-inputs]

layout(push_constant) uniform Push {
    mat4 view_projection;
} push;

layout(location = 0) out vec3 out_normal;
layout(location = 1) out vec3 out_colour;

void main() {
    // [instance-transform]
    // Boxes never rotate: scale the corner by the half extents, move it to
    // the centre. Scaling along the axes leaves an axis-aligned face's normal
    // as it was, so the normal needs no matrix.
    vec3 world = box_position + corner * box_half_extents;
    gl_Position = push.view_projection * vec4(world, 1.0);
    out_normal = normal;
    // [/instance-transform]
    out_colour = box_colour.rgb;
}
