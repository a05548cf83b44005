#pragma once
// Chapter 26's mesh shader against this device: the limit its outputs must
// fit (maxMeshOutputMemorySize, by the specification's formula) and the
// workgroup size its preferences ask for. Pure functions of the device's
// VkPhysicalDeviceMeshShaderPropertiesEXT, so that devices other than the one
// at hand are unit-tested (tests/unit/test_mesh_limits.cpp).

#include "meshlets.hpp"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>

namespace ch26 {

// [output-memory]
// What meshlets.mesh writes, in 32-bit scalars; every output takes whole
// locations of four. Per vertex: gl_Position, out_normal and out_meshlet,
// three locations. Per primitive: only the indices, which do not count.
constexpr uint32_t kScalarsPerVertex = 3 * 4, kScalarsPerPrimitive = 0;

inline uint32_t round_up(uint32_t n, uint32_t granularity) {
    granularity = std::max(granularity, 1u);
    return (n + granularity - 1) / granularity * granularity;
}

// The specification's measure of a mesh shader's output memory (one view):
// bytes per vertex times the declared most vertices, rounded up to the
// device's granularity, plus the same for primitives. It must not pass
// maxMeshOutputMemorySize; what counts is the shader's declared maxima, not
// what one workgroup writes, so smaller meshlets would not help.
inline uint32_t mesh_output_bytes(const VkPhysicalDeviceMeshShaderPropertiesEXT& device) {
    return kScalarsPerVertex * 4 * round_up(kMeshVertices, device.meshOutputPerVertexGranularity) +
           kScalarsPerPrimitive * 4 *
               round_up(kMeshTriangles, device.meshOutputPerPrimitiveGranularity);
}
// [/output-memory]

// [workgroup-size]
// How many invocations a mesh shader workgroup has (meshlets.mesh's
// constant 0). Every size draws the same picture: the loops step by the
// workgroup's size. Where the device prefers each invocation to write its own
// vertex and primitive (prefersLocalInvocation*Output), one invocation per
// vertex and per triangle, 128 for 64 and 124, if that is within its
// preferred size; else 32, or less where the device prefers fewer.
struct MeshWorkgroup {
    uint32_t size;
    const char* why;
};
inline MeshWorkgroup choose_mesh_workgroup(const VkPhysicalDeviceMeshShaderPropertiesEXT& device) {
    const uint32_t preferred =
        std::min(device.maxPreferredMeshWorkGroupInvocations, device.maxMeshWorkGroupInvocations);
    const uint32_t one_each = std::bit_ceil(std::max(kMeshVertices, kMeshTriangles));
    const bool local = device.prefersLocalInvocationVertexOutput == VK_TRUE ||
                       device.prefersLocalInvocationPrimitiveOutput == VK_TRUE;
    if (local && one_each <= preferred)
        return {one_each, "one invocation per vertex and per triangle, as the device prefers"};
    const uint32_t size = std::min(kMeshWorkgroup, std::bit_floor(std::max(preferred, 1u)));
    return {size, size < kMeshWorkgroup ? "the most the device prefers"
                                        : "each invocation writes two vertices and four triangles"};
}
// [/workgroup-size]

}  // namespace ch26
