#pragma once
// Buffers and images with their own memory. The runner needs them from chapter
// 03 on (its colour target, the screenshot read-back); chapter 05 explains
// memory types, chapter 09 images in full, and chapter 21 multisampled,
// transient attachments (create_attachment_image).

#include "vkt/core/check.hpp"
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

// An image the device cannot hold: larger than its largest image of that
// format (maxResourceSize), its largest allocation (maxMemoryAllocationSize)
// or its memory heap (past_limit: too large, whatever else is in memory), or
// within them all its allocation or bind answered out of memory (the memory
// is full, or too full for it). It carries the image's size, so that
// whoever chose that size can say so (the runner names --size), where the
// failing call's name alone would tell a reader nothing. `why` says which
// limit, or which call failed.
class ImageTooLarge : public Error {
public:
    ImageTooLarge(const std::string& why, VkExtent2D extent, VkSampleCountFlagBits samples,
                  VkDeviceSize bytes, bool past_limit)
        : Error(why), extent_(extent), samples_(samples), bytes_(bytes), past_limit_(past_limit) {}
    VkExtent2D extent() const { return extent_; }
    VkSampleCountFlagBits samples() const { return samples_; }
    VkDeviceSize bytes() const { return bytes_; }  // what it needs, at least
    bool past_limit() const { return past_limit_; }

private:
    VkExtent2D extent_;
    VkSampleCountFlagBits samples_;
    VkDeviceSize bytes_;
    bool past_limit_;
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
