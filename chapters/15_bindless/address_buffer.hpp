#pragma once
// Chapter 15's buffers that shaders reach through a GPU address (buffer
// device address): the vertices and the per-object records, read through
// 64-bit pointers passed in push constants instead of through descriptors.

#include "vkt/core/check.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/resources/upload.hpp"

namespace ch15 {

// [address-buffer]
// A device-local buffer whose GPU address shaders may use, filled with data.
// Two things differ from an ordinary buffer: the usage SHADER_DEVICE_ADDRESS,
// and the memory must be allocated with the DEVICE_ADDRESS flag (the feature
// bufferDeviceAddress allows both). vkGetBufferDeviceAddress then gives the
// 64-bit address of its first byte.
inline vkt::Buffer create_address_buffer(const vkt::Gpu& gpu, const void* data, VkDeviceSize size,
                                         VkDeviceAddress& address) {
    vkt::Buffer out;
    out.size = size;
    const VkBufferCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
        .usage = VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
    };
    VkBuffer buffer;
    VKT_CHECK(vkCreateBuffer(gpu.device, &info, nullptr, &buffer));
    out.buffer = vkt::BufferHandle(gpu.device, buffer);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(gpu.device, buffer, &requirements);
    const VkMemoryAllocateFlagsInfo flags{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO,
        .flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT,
    };
    const VkMemoryAllocateInfo allocate{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .pNext = &flags,
        .allocationSize = requirements.size,
        .memoryTypeIndex = vkt::find_memory_type(gpu.physical, requirements.memoryTypeBits,
                                                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT),
    };
    VkDeviceMemory memory;
    VKT_CHECK(vkAllocateMemory(gpu.device, &allocate, nullptr, &memory));
    out.memory = vkt::DeviceMemory(gpu.device, memory);
    VKT_CHECK(vkBindBufferMemory(gpu.device, buffer, memory, 0));

    const VkBufferDeviceAddressInfo address_info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO,
        .buffer = buffer,
    };
    address = vkGetBufferDeviceAddress(gpu.device, &address_info);
    // [/address-buffer]

    // Filled as in chapter 05, through a staging buffer: its helper, whose
    // barrier also makes the copy visible to the shaders' loads through the
    // address.
    vkt::upload_to_buffer(gpu, buffer, data, size);
    return out;
}

}  // namespace ch15
