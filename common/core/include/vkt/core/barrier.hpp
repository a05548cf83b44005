#pragma once
// The synchronization2 image barrier of chapter 03, in one call: wait for
// src_stage's src_access to finish, change the image's layout, and make the
// result visible to dst_stage's dst_access.

#include <vulkan/vulkan.h>

namespace vkt {

void image_barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout old_layout,
                   VkImageLayout new_layout, VkPipelineStageFlags2 src_stage,
                   VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                   VkAccessFlags2 dst_access,
                   VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

// The same over part of the image: some mip levels or layers (chapter 09's
// mip chain changes layout one level at a time).
void image_barrier(VkCommandBuffer cmd, VkImage image, const VkImageSubresourceRange& range,
                   VkImageLayout old_layout, VkImageLayout new_layout,
                   VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                   VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

// A global barrier, over all memory rather than one resource: what an upload
// (chapter 05), a read-back to the host (chapter 16) and an acceleration
// structure's build (chapter 24) need before the next command reads.
void memory_barrier(VkCommandBuffer cmd, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

}  // namespace vkt
