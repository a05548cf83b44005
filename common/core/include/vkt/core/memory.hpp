#pragma once
// Buffers and images with their own memory. The runner needs them from chapter
// 03 on (its colour target, the screenshot read-back); chapter 05 explains
// memory types and chapter 09 images in full.

#include "vkt/core/owned.hpp"

namespace vkt {

// The first memory type allowed by type_bits that has all of the wanted flags.
uint32_t find_memory_type(VkPhysicalDevice physical, uint32_t type_bits,
                          VkMemoryPropertyFlags wanted);

// One allocation for one buffer or image, of the first memory type that
// suits `requirements` and has `properties`: fine for the handful the runner
// and early chapters make (a real allocator suballocates; see chapter 05).
DeviceMemory allocate_memory(VkPhysicalDevice physical, VkDevice device,
                             const VkMemoryRequirements& requirements,
                             VkMemoryPropertyFlags properties);

struct Buffer {
    BufferHandle buffer;
    DeviceMemory memory;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // set for host-visible buffers, mapped for their lifetime
};

Buffer create_buffer(VkPhysicalDevice physical, VkDevice device, VkDeviceSize size,
                     VkBufferUsageFlags usage, VkMemoryPropertyFlags properties);

struct Image {
    ImageHandle image;
    DeviceMemory memory;
    ImageView view;  // declared last, so destroyed first
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    uint32_t mip_levels = 1;  // chapter 09: a texture's mip chain

    Image() = default;
    Image(Image&&) = default;
    // Replacing an image (a resized target) destroys the old view before the
    // old image, as the destructor does; the default would go member by member.
    Image& operator=(Image&& other) noexcept {
        view.reset();
        image = std::move(other.image);
        memory = std::move(other.memory);
        view = std::move(other.view);
        format = other.format;
        extent = other.extent;
        mip_levels = other.mip_levels;
        return *this;
    }
};

// A 2D image in device-local memory, one mip level, one layer, with a view.
Image create_image_2d(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                      VkExtent2D extent, VkImageUsageFlags usage, VkImageAspectFlags aspect);

// The same with `mip_levels` mip levels (chapter 09); the view sees all of them.
Image create_image_2d_mips(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                           VkExtent2D extent, uint32_t mip_levels, VkImageUsageFlags usage,
                           VkImageAspectFlags aspect);

}  // namespace vkt
