#include "vkt/resources/upload.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"

#include <cstring>

namespace vkt {

void one_time_submit(const Gpu& gpu, const std::function<void(VkCommandBuffer)>& commands) {
    CommandPool pool =
        create_command_pool(gpu.device, gpu.queue_family, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
    VkCommandBufferAllocateInfo allocate{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
        .commandPool = pool,
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
        .commandBufferCount = 1,
    };
    VkCommandBuffer cmd;  // freed with its pool
    VKT_CHECK(vkAllocateCommandBuffers(gpu.device, &allocate, &cmd));
    VkCommandBufferBeginInfo begin{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
    commands(cmd);
    VKT_CHECK(vkEndCommandBuffer(cmd));

    Fence done = create_fence(gpu.device, false);
    VkCommandBufferSubmitInfo command{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
        .commandBuffer = cmd,
    };
    VkSubmitInfo2 submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
        .commandBufferInfoCount = 1,
        .pCommandBufferInfos = &command,
    };
    VKT_CHECK(vkQueueSubmit2(gpu.queue, 1, &submit, done));
    VkFence fence = done;
    VKT_CHECK(vkWaitForFences(gpu.device, 1, &fence, VK_TRUE, UINT64_MAX));
}

Buffer create_host_buffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage) {
    return create_buffer(
        gpu.physical, gpu.device, size, usage,
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

void upload_to_buffer(const Gpu& gpu, VkBuffer buffer, const void* data, VkDeviceSize size) {
    Buffer staging = create_host_buffer(gpu, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.mapped, data, size);  // coherent: no flush needed
    one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        VkBufferCopy region{.srcOffset = 0, .dstOffset = 0, .size = size};
        vkCmdCopyBuffer(cmd, staging.buffer, buffer, 1, &region);
        // Waiting for the fence tells the CPU the copy is done, but it is no
        // memory dependency for later GPU work: this barrier makes the copy
        // visible to any read by any later command on the queue.
        memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    });
}

Buffer create_device_buffer(const Gpu& gpu, const void* data, VkDeviceSize size,
                            VkBufferUsageFlags usage) {
    if (size == 0) throw Error("create_device_buffer: an empty buffer cannot be created");
    Buffer buffer =
        create_buffer(gpu.physical, gpu.device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    upload_to_buffer(gpu, buffer.buffer, data, size);
    return buffer;
}

}  // namespace vkt
