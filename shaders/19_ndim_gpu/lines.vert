#version 450
// Chapter 19's vertex shader: no vertex attributes at all. The index buffer
// holds each edge's two vertex numbers; gl_VertexIndex (that number plus the
// draw's vertexOffset) says which vertex to pull from the storage buffer.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

layout(location = 0) out vec3 colour;
out gl_PerVertex {
    vec4 gl_Position;
    float gl_ClipDistance[1];
};

// Chapter 18's depth_colour: blue far (t = -1), orange near (t = +1), linear.
vec3 depth_colour(float t) {
    t = clamp(0.5 + 0.5 * t, 0.0, 1.0);
    return vec3(0.10 + 0.90 * t, 0.30 + 0.15 * t, 1.00 - 0.90 * t);
}

// [main]
void main() {
    vec2 clip;
    float depth;
    const bool visible = transform_and_project(gl_VertexIndex, push.object, clip, depth);
    gl_Position = vec4(clip, 0.0, 1.0);
    // A line with a clipped end must vanish whole, as on the CPU. A clip
    // distance of -1e30 there cuts the line 1e-30 of its length from the
    // visible end: nothing is left to cover a pixel.
    gl_ClipDistance[0] = visible ? 1.0 : -1.0e30;
    colour = depth_colour(depth);
}
// [/main]
