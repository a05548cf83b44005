#version 450
// --verify: the same transform as lines.vert (ndim.glsl), drawn by the same
// draws, but each vertex also writes where it landed into a storage buffer,
// which the CPU reads back and compares with vkt::ndim. Writing from a vertex
// shader needs the vertexPipelineStoresAndAtomics feature.
#extension GL_GOOGLE_include_directive : require
#include "ndim.glsl"

// [capture]
// Entry object * vertex_count + vertex: (clip x, clip y, visible, 1). The
// last 1 shows the entry was written; a vertex shared by several edges may
// run several times and writes the same value each time.
layout(set = 0, binding = 2, std430) writeonly buffer Capture {
    vec4 captured[];
};

void main() {
    vec2 clip;
    float depth;
    const bool visible = transform_and_project(gl_VertexIndex, push.object, clip, depth);
    captured[push.object * push.vertex_count + gl_VertexIndex] =
        vec4(clip, visible ? 1.0 : 0.0, 1.0);
    gl_Position = vec4(clip, 0.0, 1.0);
}
// [/capture]
