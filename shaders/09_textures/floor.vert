#version 450
// Chapter 09: a large square floor, two triangles made from gl_VertexIndex
// (no vertex buffer needed for four corners), in the plane y = 0.

// [floor-vertex]
layout(push_constant) uniform Push {
    mat4 view_projection;
    float scroll;  // how far the texture has slid towards the camera, in metres
} push;

layout(location = 0) out vec2 uv;

const float kHalfSize = 100.0;  // the floor spans -100 .. 100 m in x and z
const float kTile = 1.0;        // one copy of the texture per metre: it repeats
const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1),
                                vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
    vec2 xz = kCorners[gl_VertexIndex] * kHalfSize;
    // Texture coordinates beyond 0..1: uv runs from -100 to 100, and the
    // sampler's REPEAT addressing tiles the texture 200 times across the floor.
    uv = (xz + vec2(0.0, push.scroll)) / kTile;
    gl_Position = push.view_projection * vec4(xz.x, 0.0, xz.y, 1.0);
}
// [/floor-vertex]
