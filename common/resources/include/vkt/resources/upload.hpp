#pragma once
// Getting data into device-local memory, the tidy form of chapter 05: record a
// few commands into a throw-away command buffer, submit them, wait. Fine for
// loading; never inside the frame loop.

#include "vkt/core/memory.hpp"

#include <functional>

namespace vkt {

// The handles an upload needs (Context::gpu() gives them to a chapter).
struct Gpu {
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queue_family = 0;
};

// Records `commands` into a one-time command buffer, submits it, and waits for
// the queue to finish it.
void one_time_submit(const Gpu& gpu, const std::function<void(VkCommandBuffer)>& commands);

// A device-local buffer with `usage` (plus TRANSFER_DST) holding a copy of
// data[0..size), filled through a host-visible staging buffer. The copy is
// finished and visible to every later command on the queue when this returns.
Buffer create_device_buffer(const Gpu& gpu, const void* data, VkDeviceSize size,
                            VkBufferUsageFlags usage);

// Copies data[0..size) into the start of `buffer` (made with TRANSFER_DST)
// through a host-visible staging buffer, as create_device_buffer does; for a
// buffer the caller made itself (chapter 15: memory with a GPU address).
// The copy is finished and visible to every later command when this returns.
void upload_to_buffer(const Gpu& gpu, VkBuffer buffer, const void* data, VkDeviceSize size);

// A host-visible, host-coherent buffer, mapped for its lifetime: for data the
// CPU rewrites every frame (one per frame in flight, see chapter 07).
Buffer create_host_buffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage);

}  // namespace vkt
