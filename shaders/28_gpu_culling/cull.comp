#version 460
#extension GL_GOOGLE_include_directive : require

// Chapter 28's cull pass: one invocation per instance decides whether it can
// be seen (instance_cull.glsl) and, if so, appends its draw command to a
// list; the list's length is the count vkCmdDrawIndexedIndirectCount reads.

#include "culling_data.glsl"
#include "instance_cull.glsl"

layout(local_size_x = 64) in;  // main.cpp's kCullGroup

// VkDrawIndexedIndirectCommand, five words.
struct DrawCommand {
    uint index_count, instance_count, first_index;
    int vertex_offset;
    uint first_instance;
};
layout(std430, set = 0, binding = 2) writeonly buffer Draws { DrawCommand draws[]; };

// [append]
void append(uint list, uint i, uint mesh) {
    uint slot = atomicAdd(counts[list], 1);
    draws[list * push.instance_count + slot] =
        DrawCommand(meshes[mesh].index_count, 1, meshes[mesh].first_index, 0, i);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.instance_count) return;
    uint list = cull_instance(i);
    if (list != NOT_DRAWN) append(list, i, uint(instances[i].box_half.w));
}
// [/append]
