#version 450
// [instance-inputs]
// Per vertex (binding 0, advancing every vertex): a corner of the unit cube
// (-1..1) and its face's normal.
layout(location = 0) in vec3 corner;
layout(location = 1) in vec3 normal;
// Per instance (binding 1, advancing once per box): where the box is, how
// big, how it is turned, what colour. The same 24 corners are drawn once for
// every box.
layout(location = 2) in vec3 box_position;
layout(location = 3) in vec3 box_half_extents;
layout(location = 4) in vec4 box_orientation;  // unit quaternion: xyz, then w
layout(location = 5) in vec4 box_colour;       // R8G8B8A8_UNORM: 0..255 read as 0..1
// [/instance-inputs]

layout(push_constant) uniform Push {
    mat4 view_projection;
} push;

layout(location = 0) out vec3 out_normal;
layout(location = 1) out vec3 out_colour;

// [rotate]
// Turns v by the unit quaternion q: v + 2 u x (u x v + w v), with u = q.xyz.
// The same as multiplying by q's rotation matrix, without building the
// matrix for every vertex.
vec3 rotate(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}
// [/rotate]

void main() {
    // [instance-transform]
    // Scale the corner by the half extents in the box's own frame, turn it,
    // move it to the centre. The normal is turned the same way: a rotation
    // keeps right angles, so it needs no inverse transpose, and scaling
    // along the box's own axes leaves an axis-aligned face's normal as it was.
    vec3 world = box_position + rotate(box_orientation, corner * box_half_extents);
    gl_Position = push.view_projection * vec4(world, 1.0);
    out_normal = rotate(box_orientation, normal);
    // [/instance-transform]
    out_colour = box_colour.rgb;
}
