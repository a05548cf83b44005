#include "vkt/resources/compute.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>
#include <numeric>
#include <string>

namespace vkt {

uint64_t max_items_per_dispatch(const VkPhysicalDeviceLimits& limits, uint32_t group,
                                uint32_t item_size) {
    if (group == 0 || item_size == 0)
        throw std::invalid_argument("max_items_per_dispatch: zero group or item size");
    // Whole workgroups only, and a chunk's bytes a multiple of the offset
    // alignment: a step of `unit` items satisfies both.
    const uint64_t alignment = std::max<uint64_t>(limits.minStorageBufferOffsetAlignment, 1);
    const uint64_t bytes_per_group = uint64_t(group) * item_size;
    const uint64_t unit = group * (alignment / std::gcd(alignment, bytes_per_group));
    const uint64_t by_groups = uint64_t(limits.maxComputeWorkGroupCount[0]) * group;
    const uint64_t by_range = limits.maxStorageBufferRange / item_size;
    // A chunk's count is a uint32_t (it reaches the shader as one).
    const uint64_t most = std::min({by_groups, by_range, uint64_t(UINT32_MAX)});
    const uint64_t items = most / unit * unit;
    if (items == 0)
        throw Error("one workgroup of " + std::to_string(group) + " items of " +
                    std::to_string(item_size) + " bytes exceeds this device's limits");
    return items;
}

std::vector<DispatchChunk> split_dispatch(uint64_t n, uint32_t group, uint64_t max_items) {
    if (max_items == 0 || max_items % group != 0)
        throw std::invalid_argument(
            "split_dispatch: max_items must be a positive multiple of group");
    std::vector<DispatchChunk> chunks;
    for (uint64_t first = 0; first < n; first += max_items) {
        const auto count = uint32_t(std::min(max_items, n - first));
        chunks.push_back({first, count, uint32_t(dispatch_count(count, group))});
    }
    return chunks;
}

Pipeline create_compute_pipeline(VkDevice device, VkShaderModule shader, VkPipelineLayout layout,
                                 const VkSpecializationInfo* specialization) {
    VkComputePipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
        .stage =
            {
                .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                .module = shader,
                .pName = "main",
                .pSpecializationInfo = specialization,
            },
        .layout = layout,
    };
    VkPipeline pipeline;
    VKT_CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return Pipeline(device, pipeline);
}

void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 src_stage,
                    VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                    VkAccessFlags2 dst_access, VkDeviceSize offset, VkDeviceSize size) {
    VkBufferMemoryBarrier2 barrier{
        .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
        .srcStageMask = src_stage,
        .srcAccessMask = src_access,
        .dstStageMask = dst_stage,
        .dstAccessMask = dst_access,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .buffer = buffer,
        .offset = offset,
        .size = size,
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .bufferMemoryBarrierCount = 1,
        .pBufferMemoryBarriers = &barrier,
    };
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace vkt
