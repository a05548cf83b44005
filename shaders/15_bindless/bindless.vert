#version 460
#extension GL_EXT_buffer_reference : require

// [buffer-references]
// No vertex input state and no storage-buffer descriptors: the shader reads
// vertices and objects through 64-bit GPU addresses that arrive in push
// constants. A buffer_reference block is a pointer type; indexing it loads
// from address + index * stride. std430: a Vertex is 32 bytes, an Object 96,
// exactly as the C++ structs in main.cpp.
struct Vertex {
    vec4 position_u;  // xyz: position, w: texture u
    vec4 normal_v;    // xyz: normal, w: texture v
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer Vertices {
    Vertex vertex[];
};

struct Object {
    mat4 model;
    vec4 tint;
    uint side_texture;  // index into the texture array, for the sides
    uint top_texture;   // and for faces that look up (the lids)
    uint pad0, pad1;
};
layout(buffer_reference, std430, buffer_reference_align = 16) readonly buffer Objects {
    Object object[];
};

layout(push_constant) uniform Push {
    mat4 view_projection;
    Vertices vertices;  // a VkDeviceAddress on the C++ side
    Objects objects;
    uint resident_textures;
} push;
// [/buffer-references]

layout(location = 0) out vec3 out_normal;
layout(location = 1) out vec2 out_uv;
layout(location = 2) flat out uint out_side_texture;
layout(location = 3) flat out uint out_top_texture;
layout(location = 4) out vec3 out_tint;

void main() {
    // [pull]
    // gl_InstanceIndex is firstInstance + the instance within the draw: every
    // draw is one instance, and firstInstance is the object's index, in the
    // indirect commands and in the loop alike. gl_VertexIndex already
    // includes the draw's vertexOffset, so it indexes the shared vertex buffer.
    Object object = push.objects.object[gl_InstanceIndex];
    Vertex vertex = push.vertices.vertex[gl_VertexIndex];
    // [/pull]
    gl_Position = push.view_projection * object.model * vec4(vertex.position_u.xyz, 1.0);
    // Rotation and uniform scale only: the model matrix's 3x3 part keeps
    // normals perpendicular (the fragment shader normalises).
    out_normal = mat3(object.model) * vertex.normal_v.xyz;
    out_uv = vec2(vertex.position_u.w, vertex.normal_v.w) * object.tint.w;  // w: repeats
    out_side_texture = object.side_texture;
    out_top_texture = object.top_texture;
    out_tint = object.tint.rgb;
}
