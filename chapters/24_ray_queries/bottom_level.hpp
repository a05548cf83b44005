#pragma once
// Chapter 24's bottom-level acceleration structures: one per mesh of the
// scene, built from the shared vertex and index buffers by address, all in
// one command, then compacted.

#include "acceleration.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/resources/align.hpp"
#include "vkt/scene/meshes.hpp"

#include <cstdio>
#include <span>
#include <vector>

namespace ch24 {

// What the bottom level's builds cost and saved, for the start-up line.
struct BottomLevelReport {
    VkDeviceSize built_bytes = 0, compacted_bytes = 0, scratch_bytes = 0;
};

// [geometry]
// A mesh as one triangle geometry: positions (the first 12 bytes of every
// vertex) and indices, read through their buffers' GPU addresses. OPAQUE: no
// any-hit work, every hit counts.
inline VkAccelerationStructureGeometryKHR triangle_geometry(VkDeviceAddress vertices,
                                                            uint32_t vertex_count,
                                                            VkIndexType index_type,
                                                            VkDeviceAddress indices) {
    return {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR,
        .geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR,
        .geometry =
            {.triangles =
                 {
                     .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR,
                     .vertexFormat = VK_FORMAT_R32G32B32_SFLOAT,
                     .vertexData = {.deviceAddress = vertices},
                     .vertexStride = sizeof(vkt::shapes::Vertex),
                     .maxVertex = vertex_count - 1,
                     .indexType = index_type,
                     .indexData = {.deviceAddress = indices},
                 }},
        .flags = VK_GEOMETRY_OPAQUE_BIT_KHR,
    };
}
// [/geometry]

// [build-info]
// One bottom level's build of one geometry: PREFER_FAST_TRACE (it is built
// once and traced every frame), ALLOW_COMPACTION (so that the device can
// later tell how small the finished structure can be). The destination and
// the scratch address are filled in once they exist.
inline VkAccelerationStructureBuildGeometryInfoKHR bottom_level_build(
    const VkAccelerationStructureGeometryKHR* geometry) {
    return {
        .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR,
        .type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
        .flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                 VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR,
        .mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR,
        .geometryCount = 1,
        .pGeometries = geometry,
    };
}
// [/build-info]

// The builds' writes made visible to what reads the structures next in the
// command buffer: the query below, or the copies of compaction.
inline void after_builds(VkCommandBuffer cmd) {
    vkt::memory_barrier(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                        VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR,
                        VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                        VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR);
}

// [query-sizes]
// After the builds, in the same command buffer: each finished structure's
// compacted size into its slot of `pool`. The size is known only once a
// build has finished, so a barrier first (the builds' writes before the
// query's read), then the pool's slots cleared, then the query.
inline void write_compacted_sizes(VkCommandBuffer cmd, const RayFunctions& ray,
                                  std::span<const AccelerationStructure> built, VkQueryPool pool) {
    std::vector<VkAccelerationStructureKHR> handles;
    for (const AccelerationStructure& structure : built) handles.push_back(structure.get());
    after_builds(cmd);
    vkCmdResetQueryPool(cmd, pool, 0, uint32_t(handles.size()));
    ray.cmd_write_properties(cmd, uint32_t(handles.size()), handles.data(),
                             VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, pool, 0);
}
// [/query-sizes]

inline std::vector<AccelerationStructure> build_bottom_levels(
    const vkt::Gpu& gpu, const RayFunctions& ray, VkDeviceSize scratch_alignment,
    std::span<const vkt::shapes::MeshRange> meshes, VkDeviceAddress vertices, uint32_t vertex_count,
    VkDeviceAddress indices, BottomLevelReport& report) {
    const size_t count = meshes.size();
    std::vector<VkAccelerationStructureGeometryKHR> geometries(count);
    std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges(count);
    for (size_t i = 0; i < count; ++i) {
        geometries[i] = triangle_geometry(vertices, vertex_count, VK_INDEX_TYPE_UINT16,
                                          indices + meshes[i].first_index * sizeof(uint16_t));
        ranges[i] = {.primitiveCount = meshes[i].index_count / 3};
    }

    // [sizes]
    // How big each structure and its scratch space must be: a question
    // asked of the device, which alone knows its layout.
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> builds(count);
    std::vector<AccelerationStructure> built(count);
    std::vector<VkDeviceSize> scratch_offsets(count);
    VkDeviceSize scratch_size = 0;
    for (size_t i = 0; i < count; ++i) {
        builds[i] = bottom_level_build(&geometries[i]);
        VkAccelerationStructureBuildSizesInfoKHR sizes{
            .sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
        ray.build_sizes(gpu.device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &builds[i],
                        &ranges[i].primitiveCount, &sizes);
        built[i] = AccelerationStructure(gpu, ray, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                                         sizes.accelerationStructureSize);
        builds[i].dstAccelerationStructure = built[i].get();
        report.built_bytes += sizes.accelerationStructureSize;
        // The builds run at once, each in its own part of one scratch
        // buffer, whose start must be a multiple of the device's
        // minAccelerationStructureScratchOffsetAlignment.
        scratch_offsets[i] = vkt::align_up(scratch_size, scratch_alignment);
        scratch_size = scratch_offsets[i] + sizes.buildScratchSize;
    }
    report.scratch_bytes = scratch_size;
    // The buffer's own address is only as aligned as its memory: one
    // alignment more than the parts need, and the parts start at its
    // address rounded up.
    AddressBuffer scratch = create_address_buffer(
        gpu, vkt::align_up(scratch_size, scratch_alignment) + scratch_alignment,
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    const VkDeviceAddress scratch_base = vkt::align_up(scratch.address, scratch_alignment);
    for (size_t i = 0; i < count; ++i)
        builds[i].scratchData.deviceAddress = scratch_base + scratch_offsets[i];
    // [/sizes]

    // [query-pool]
    // For compaction: a query pool of one slot per structure, each to hold
    // that structure's compacted size once its build has finished.
    const VkQueryPoolCreateInfo pool_info{
        .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
        .queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR,
        .queryCount = uint32_t(count),
    };
    VkQueryPool raw_pool;
    VKT_CHECK(vkCreateQueryPool(gpu.device, &pool_info, nullptr, &raw_pool));
    const vkt::QueryPool pool(gpu.device, raw_pool);
    // [/query-pool]

    // [build]
    // One command builds them all, each geometry with its ranges (here one,
    // its triangle count); the same command then asks how small each finished
    // structure can be (24b: compaction).
    std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> range_pointers(count);
    for (size_t i = 0; i < count; ++i) range_pointers[i] = &ranges[i];
    vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        ray.cmd_build(cmd, uint32_t(count), builds.data(), range_pointers.data());
        write_compacted_sizes(cmd, ray, built, pool);
    });
    // [/build]

    // [compact]
    // The query's answers, read back once the submit has finished: one
    // compacted size per structure, in bytes.
    std::vector<VkDeviceSize> compacted_sizes(count);
    VKT_CHECK(vkGetQueryPoolResults(
        gpu.device, pool, 0, uint32_t(count), count * sizeof(VkDeviceSize), compacted_sizes.data(),
        sizeof(VkDeviceSize), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));

    // Compaction: a structure of exactly the compacted size, the built one
    // copied into it (mode COMPACT), and the built one destroyed.
    std::vector<AccelerationStructure> compacted(count);
    for (size_t i = 0; i < count; ++i) {
        compacted[i] = AccelerationStructure(
            gpu, ray, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, compacted_sizes[i]);
        report.compacted_bytes += compacted_sizes[i];
    }
    vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        after_builds(cmd);
        for (size_t i = 0; i < count; ++i) {
            const VkCopyAccelerationStructureInfoKHR copy{
                .sType = VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR,
                .src = built[i].get(),
                .dst = compacted[i].get(),
                .mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR,
            };
            ray.cmd_copy(cmd, &copy);
        }
    });
    built.clear();  // the copies are finished (one_time_submit waited): destroy the originals
    // [/compact]
    return compacted;
}

}  // namespace ch24
