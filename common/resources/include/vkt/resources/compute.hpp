#pragma once
// Compute, the tidy form of chapter 13: how many workgroups cover n items,
// how many items one dispatch may cover on a device (and so how a large job is
// split into several dispatches), a compute pipeline in one call, and a
// synchronization2 barrier on a buffer.

#include "vkt/core/owned.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace vkt {

// [dispatch-count]
// ceil(n / group): the number of workgroups of `group` invocations that cover
// n items. Unless n is a multiple of group the last workgroup is partly idle,
// so the shader must check its index against n. Written without n + group - 1,
// which would overflow for n near the top of the range.
constexpr uint64_t dispatch_count(uint64_t n, uint32_t group) {
    if (group == 0) throw std::invalid_argument("dispatch_count: a workgroup of 0 invocations");
    return n / group + (n % group != 0 ? 1 : 0);
}
// [/dispatch-count]

// The most items, each item_size bytes in one storage buffer and one
// invocation each, that a single dispatch of `group`-wide workgroups may
// cover on a device with these limits: at most maxComputeWorkGroupCount[0]
// workgroups, at most maxStorageBufferRange bytes seen through one
// descriptor, and whole workgroups, so that the next dispatch's first item
// starts on a workgroup boundary whose byte offset is a multiple of
// minStorageBufferOffsetAlignment. Throws Error if not even one workgroup fits.
uint64_t max_items_per_dispatch(const VkPhysicalDeviceLimits& limits, uint32_t group,
                                uint32_t item_size);

// One dispatch's share of n items: items [first, first + count).
struct DispatchChunk {
    uint64_t first = 0;
    uint32_t count = 0;
    uint32_t groups = 0;  // dispatch_count(count, group)
};

// n items in dispatches of at most max_items each (a multiple of group, as
// max_items_per_dispatch returns); every chunk but the last is full.
std::vector<DispatchChunk> split_dispatch(uint64_t n, uint32_t group, uint64_t max_items);

// A compute pipeline of one shader (entry point "main") and a layout; the
// specialization constants, if any, set its workgroup size, say.
Pipeline create_compute_pipeline(VkDevice device, VkShaderModule shader, VkPipelineLayout layout,
                                 const VkSpecializationInfo* specialization = nullptr);

// A synchronization2 buffer memory barrier on buffer[offset, offset + size):
// wait for src_stage's src_access to finish and make its result visible to
// dst_stage's dst_access (chapter 13: compute writes, then vertex input reads).
void buffer_barrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 src_stage,
                    VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                    VkAccessFlags2 dst_access, VkDeviceSize offset = 0,
                    VkDeviceSize size = VK_WHOLE_SIZE);

}  // namespace vkt
