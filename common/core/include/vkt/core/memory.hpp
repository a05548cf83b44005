#pragma once
// Buffers and images with their own memory. The runner needs them from chapter
// 03 on (its colour target, the screenshot read-back); chapter 05 explains
// memory types, chapter 09 images in full, and chapter 21 multisampled,
// transient attachments (create_attachment_image).

#include "vkt/core/owned.hpp"

namespace vkt {

// The first memory type allowed by type_bits that has all of the wanted flags.
uint32_t find_memory_type(VkPhysicalDevice physical, uint32_t type_bits,
                          VkMemoryPropertyFlags wanted);

// The same, or UINT32_MAX where no type has them (chapter 21 asks whether the
// device has LAZILY_ALLOCATED memory at all).
uint32_t find_memory_type_or_none(VkPhysicalDevice physical, uint32_t type_bits,
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
    // Chapter 21: samples per pixel, whether the memory is LAZILY_ALLOCATED
    // (create_attachment_image), and how much memory the image asked for.
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool lazily_allocated = false;
    VkDeviceSize bytes = 0;

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
        samples = other.samples;
        lazily_allocated = other.lazily_allocated;
        bytes = other.bytes;
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

// Chapter 21: an attachment of `samples` samples per pixel (one mip level).
// With `transient` its contents never outlive a render pass (they are
// resolved or thrown away at its end): usage gains TRANSIENT_ATTACHMENT, and
// the memory is DEVICE_LOCAL | LAZILY_ALLOCATED where the device has such a
// type (a tiling GPU may then keep the samples in on-chip memory and never
// back them), plain DEVICE_LOCAL where it has none; Image::lazily_allocated
// says which. The defaults make the same image as create_image_2d.
Image create_attachment_image(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                              VkExtent2D extent, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                              VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT,
                              bool transient = false);

}  // namespace vkt
