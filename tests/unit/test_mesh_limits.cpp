// Chapter 26's mesh shader against devices other than the one at hand
// (chapters/26_mesh_shaders/mesh_limits.hpp): the output memory by the
// specification's formula, and the workgroup size chosen from the device's
// preferences. The pretend devices' numbers are those such devices report.
#include "../../chapters/26_mesh_shaders/mesh_limits.hpp"

#include <catch2/catch_test_macros.hpp>

namespace {

VkPhysicalDeviceMeshShaderPropertiesEXT device(uint32_t preferred_mesh, bool local_vertex,
                                               bool local_primitive) {
    VkPhysicalDeviceMeshShaderPropertiesEXT p{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_PROPERTIES_EXT};
    p.maxMeshWorkGroupInvocations = 128;  // the specification's least
    p.maxMeshOutputMemorySize = 32768;    // its least as well
    p.meshOutputPerVertexGranularity = 1;
    p.meshOutputPerPrimitiveGranularity = 1;
    p.maxPreferredMeshWorkGroupInvocations = preferred_mesh;
    p.prefersLocalInvocationVertexOutput = local_vertex ? VK_TRUE : VK_FALSE;
    p.prefersLocalInvocationPrimitiveOutput = local_primitive ? VK_TRUE : VK_FALSE;
    return p;
}

}  // namespace

TEST_CASE("the mesh workgroup follows the device's preferences", "[meshlets]") {
    // lavapipe: prefers local-invocation output, up to 128 invocations: one
    // invocation per vertex and per triangle (124 of them) fits.
    CHECK(ch26::choose_mesh_workgroup(device(128, true, true)).size == 128);
    // A device that only prefers local primitive output is served the same way.
    CHECK(ch26::choose_mesh_workgroup(device(256, false, true)).size == 128);
    // No such preference (a device that wants 32-wide workgroups): 32.
    CHECK(ch26::choose_mesh_workgroup(device(32, false, false)).size == 32);
    CHECK(ch26::choose_mesh_workgroup(device(256, false, false)).size == 32);
    // Prefers local output but fewer than 128 invocations: not one each, and
    // no more than it prefers.
    CHECK(ch26::choose_mesh_workgroup(device(64, true, true)).size == 32);
    CHECK(ch26::choose_mesh_workgroup(device(16, true, true)).size == 16);
    CHECK(ch26::choose_mesh_workgroup(device(24, false, false)).size == 16);
}

TEST_CASE("the mesh shader's output memory is counted as the specification counts it",
          "[meshlets]") {
    // Three locations of four scalars per vertex, 64 vertices, no
    // per-primitive outputs: 12 x 4 x 64 = 3072 bytes.
    VkPhysicalDeviceMeshShaderPropertiesEXT p = device(128, true, true);
    CHECK(ch26::mesh_output_bytes(p) == 3072);
    // A granularity of 32 vertices rounds 64 to 64; one of 48 rounds it to 96.
    p.meshOutputPerVertexGranularity = 32;
    CHECK(ch26::mesh_output_bytes(p) == 3072);
    p.meshOutputPerVertexGranularity = 48;
    CHECK(ch26::mesh_output_bytes(p) == 12 * 4 * 96);
    // Primitive granularity costs nothing: no per-primitive outputs.
    p.meshOutputPerPrimitiveGranularity = 128;
    CHECK(ch26::mesh_output_bytes(p) == 12 * 4 * 96);
}
