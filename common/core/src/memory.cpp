#include "vkt/core/memory.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

namespace vkt {

uint32_t find_memory_type_or_none(VkPhysicalDevice physical, uint32_t type_bits,
                                  VkMemoryPropertyFlags wanted) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    return UINT32_MAX;
}

uint32_t find_memory_type(VkPhysicalDevice physical, uint32_t type_bits,
                          VkMemoryPropertyFlags wanted) {
    const uint32_t type = find_memory_type_or_none(physical, type_bits, wanted);
    if (type != UINT32_MAX) return type;
    char flags[16];
    std::snprintf(flags, sizeof flags, "0x%x", wanted);
    throw Error(std::string("no memory type has the properties ") + flags);
}

DeviceMemory allocate_memory(VkPhysicalDevice physical, VkDevice device,
                             const VkMemoryRequirements& requirements,
                             VkMemoryPropertyFlags properties) {
    VkMemoryAllocateInfo info{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = requirements.size,
        .memoryTypeIndex = find_memory_type(physical, requirements.memoryTypeBits, properties),
    };
    VkDeviceMemory memory;
    VKT_CHECK(vkAllocateMemory(device, &info, nullptr, &memory));
    return DeviceMemory(device, memory);
}

Buffer create_buffer(VkPhysicalDevice physical, VkDevice device, VkDeviceSize size,
                     VkBufferUsageFlags usage, VkMemoryPropertyFlags properties) {
    Buffer out;
    out.size = size;
    VkBufferCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
        .usage = usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
    };
    VkBuffer buffer;
    VKT_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
    out.buffer = BufferHandle(device, buffer);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, buffer, &requirements);
    out.memory = allocate_memory(physical, device, requirements, properties);
    VKT_CHECK(vkBindBufferMemory(device, buffer, out.memory, 0));
    if (properties & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
        VKT_CHECK(vkMapMemory(device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped));
    return out;
}

Image create_image_2d(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                      VkExtent2D extent, VkImageUsageFlags usage, VkImageAspectFlags aspect) {
    return create_image_2d_mips(physical, device, format, extent, 1, usage, aspect);
}

namespace {

// Bytes a texel of `format` takes, for the formats this project makes images
// of; 0 for any other (then only the allocation's own checks apply).
VkDeviceSize texel_bytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8_UNORM:
        case VK_FORMAT_S8_UINT:
            return 1;
        case VK_FORMAT_D16_UNORM:
        case VK_FORMAT_R16_SFLOAT:
            return 2;
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_UNORM:
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
        case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_R16G16_SNORM:
        case VK_FORMAT_R32_SFLOAT:
        case VK_FORMAT_R32_UINT:
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D24_UNORM_S8_UINT:
        case VK_FORMAT_X8_D24_UNORM_PACK32:
        case VK_FORMAT_D16_UNORM_S8_UINT:
            return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT:
        case VK_FORMAT_R32G32_SFLOAT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT:
            return 16;
        default:
            return 0;
    }
}

// The device's largest allocation (Vulkan 1.1) and its largest heap that
// `type_bits` may use.
std::pair<VkDeviceSize, VkDeviceSize> allocation_limits(VkPhysicalDevice physical,
                                                        uint32_t type_bits) {
    VkPhysicalDeviceMaintenance3Properties maintenance3{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                           .pNext = &maintenance3};
    vkGetPhysicalDeviceProperties2(physical, &properties);
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    VkDeviceSize heap = 0;
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if (type_bits & (1u << i))
            heap = std::max(heap, memory.memoryHeaps[memory.memoryTypes[i].heapIndex].size);
    return {maintenance3.maxMemoryAllocationSize, heap};
}

// Every image of this file: create, ask its memory requirements, allocate
// (lazily where `transient` and the device has such memory), bind, view.
Image make_image(VkPhysicalDevice physical, VkDevice device, VkFormat format, VkExtent2D extent,
                 uint32_t mip_levels, VkSampleCountFlagBits samples, bool transient,
                 VkImageUsageFlags usage, VkImageAspectFlags aspect) {
    Image out;
    out.format = format;
    out.extent = extent;
    out.mip_levels = mip_levels;
    out.samples = samples;
    VkImageCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = format,
        .extent = {extent.width, extent.height, 1},
        .mipLevels = mip_levels,
        .arrayLayers = 1,
        .samples = samples,
        .tiling = VK_IMAGE_TILING_OPTIMAL,
        .usage = transient ? usage | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT : usage,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
    };
    // Past the device's largest image of this format, vkCreateImage itself
    // is an error: ask first (its pixels alone, the least it can need).
    // A format the query does not answer for is left to vkCreateImage.
    VkImageFormatProperties limits{};
    const VkResult asked = vkGetPhysicalDeviceImageFormatProperties(
        physical, format, info.imageType, info.tiling, info.usage, 0, &limits);
    const VkDeviceSize least = VkDeviceSize(extent.width) * extent.height * samples *
                               texel_bytes(format) * (mip_levels > 1 ? 4 : 3) / 3;
    if (asked == VK_SUCCESS && least > limits.maxResourceSize)
        throw ImageTooLarge("the device's largest image of this format is " +
                                std::to_string(limits.maxResourceSize) + " bytes" +
                                " (maxResourceSize)",
                            extent, samples, least, true);
    VkImage image;
    VKT_CHECK(vkCreateImage(device, &info, nullptr, &image));
    out.image = ImageHandle(device, image);

    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, image, &requirements);
    out.bytes = requirements.size;
    const auto [largest_allocation, heap] =
        allocation_limits(physical, requirements.memoryTypeBits);
    if (requirements.size > largest_allocation)
        throw ImageTooLarge("the device's largest allocation is " +
                                std::to_string(largest_allocation) + " bytes" +
                                " (maxMemoryAllocationSize)",
                            extent, samples, requirements.size, true);
    if (requirements.size > heap)
        throw ImageTooLarge("the device's memory heap holds " + std::to_string(heap) + " bytes",
                            extent, samples, requirements.size, true);
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    constexpr VkMemoryPropertyFlags lazy = local | VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;
    out.lazily_allocated =
        transient &&
        find_memory_type_or_none(physical, requirements.memoryTypeBits, lazy) != UINT32_MAX;
    try {
        out.memory =
            allocate_memory(physical, device, requirements, out.lazily_allocated ? lazy : local);
        VKT_CHECK(vkBindImageMemory(device, image, out.memory, 0));
    } catch (const VulkanError& e) {
        if (e.result() != VK_ERROR_OUT_OF_DEVICE_MEMORY &&
            e.result() != VK_ERROR_OUT_OF_HOST_MEMORY)
            throw;
        // Within every limit, and still no memory: the device's memory is
        // full, or too full for this image.
        throw ImageTooLarge(e.what(), extent, samples, requirements.size, false);
    }

    VkImageViewCreateInfo view_info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D,
        .format = format,
        .subresourceRange = {aspect, 0, mip_levels, 0, 1},
    };
    VkImageView view;
    VKT_CHECK(vkCreateImageView(device, &view_info, nullptr, &view));
    out.view = ImageView(device, view);
    return out;
}

}  // namespace

Image create_image_2d_mips(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                           VkExtent2D extent, uint32_t mip_levels, VkImageUsageFlags usage,
                           VkImageAspectFlags aspect) {
    if (mip_levels == 0) throw Error("create_image_2d_mips: an image needs at least one mip level");
    return make_image(physical, device, format, extent, mip_levels, VK_SAMPLE_COUNT_1_BIT, false,
                      usage, aspect);
}

Image create_attachment_image(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                              VkExtent2D extent, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                              VkSampleCountFlagBits samples, bool transient) {
    return make_image(physical, device, format, extent, 1, samples, transient, usage, aspect);
}

}  // namespace vkt
