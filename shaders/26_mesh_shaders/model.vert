#version 460
#extension GL_GOOGLE_include_directive : require
// Chapter 26's comparison (--draw indirect): chapter 15's way, the whole
// model in one vkCmdDrawIndexedIndirect through the vertex shader, pulling
// its vertex from the same buffer the mesh shader reads.

#include "meshlet_data.glsl"

layout(location = 0) out vec3 out_normal;
layout(location = 1) flat out uint out_meshlet;

void main() {
    const Vertex v = vertices[gl_VertexIndex];
    gl_Position = push.clip_from_world * vec4(v.position.xyz, 1.0);
    out_normal = v.normal.xyz;
    out_meshlet = 0;
}
