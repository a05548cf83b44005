#pragma once
// Chapter 29's lesson in three calls, written out with the C API: a timeline
// semaphore, one half of a queue-family ownership transfer, and a submit that
// waits for one timeline value and signals another. main.cpp calls them.

#include "vkt/core/check.hpp"
#include "vkt/core/owned.hpp"

namespace ch29 {

// [timeline]
// A timeline semaphore is one 64-bit counter that only grows. A submit
// signals it to a value when its work is done; a submit, or the host, waits
// until it has reached a value. One semaphore serves every frame: frame N
// waits for value N, where a binary semaphore or a fence is one event that
// must be reset before it can be used again.
inline vkt::Semaphore create_timeline(VkDevice device) {
    const VkSemaphoreTypeCreateInfo type{
        .sType = VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO,
        .semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE,
        .initialValue = 0,
    };
    const VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO,
                                     .pNext = &type};
    VkSemaphore semaphore;
    VKT_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
    return vkt::Semaphore(device, semaphore);
}
// [/timeline]

// [ownership]
// An image made with VK_SHARING_MODE_EXCLUSIVE belongs to one queue family
// at a time. To hand it over, the family that has it records a release
// barrier (its source half: the writes to finish; the destination half is
// ignored) and the family that takes it records the matching acquire (the
// same families, layouts and range; its destination half: who reads next),
// after a semaphore says the release is done. With one family there is
// nothing to hand over: the release is then an ordinary barrier (families
// IGNORED) and there is no acquire, the semaphore making the writes visible.
inline void ownership_barrier(VkCommandBuffer cmd, VkImage image, uint32_t levels,
                              VkImageLayout from, VkImageLayout to, uint32_t src_family,
                              uint32_t dst_family, VkPipelineStageFlags2 src_stage,
                              VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                              VkAccessFlags2 dst_access) {
    const bool same = src_family == dst_family;
    const VkImageMemoryBarrier2 barrier{
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
        .srcStageMask = src_stage,
        .srcAccessMask = src_access,
        .dstStageMask = dst_stage,
        .dstAccessMask = dst_access,
        .oldLayout = from,
        .newLayout = to,
        .srcQueueFamilyIndex = same ? VK_QUEUE_FAMILY_IGNORED : src_family,
        .dstQueueFamilyIndex = same ? VK_QUEUE_FAMILY_IGNORED : dst_family,
        .image = image,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, 1},
    };
    const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                      .imageMemoryBarrierCount = 1,
                                      .pImageMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dependency);
}
// [/ownership]

// One submit of one command buffer, waiting for one timeline value (or none)
// and signalling one.
inline void submit(VkQueue queue, VkCommandBuffer cmd, VkSemaphore wait, uint64_t wait_value,
                   VkPipelineStageFlags2 wait_stage, VkSemaphore signal, uint64_t signal_value) {
    // [submit]
    const VkSemaphoreSubmitInfo waits{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                      .semaphore = wait,
                                      .value = wait_value,
                                      .stageMask = wait_stage};
    const VkSemaphoreSubmitInfo signals{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                        .semaphore = signal,
                                        .value = signal_value,
                                        .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT};
    const VkCommandBufferSubmitInfo command{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
                                            .commandBuffer = cmd};
    const VkSubmitInfo2 info{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
                             .waitSemaphoreInfoCount = wait ? 1u : 0u,
                             .pWaitSemaphoreInfos = &waits,
                             .commandBufferInfoCount = 1,
                             .pCommandBufferInfos = &command,
                             .signalSemaphoreInfoCount = 1,
                             .pSignalSemaphoreInfos = &signals};
    VKT_CHECK(vkQueueSubmit2(queue, 1, &info, VK_NULL_HANDLE));  // no fence: the timeline says
    // [/submit]
}

}  // namespace ch29
