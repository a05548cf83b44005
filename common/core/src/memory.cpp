#include "vkt/core/memory.hpp"

#include "vkt/core/check.hpp"

#include <cstdio>
#include <string>

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
    VkImage image;
    VKT_CHECK(vkCreateImage(device, &info, nullptr, &image));
    out.image = ImageHandle(device, image);

    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, image, &requirements);
    out.bytes = requirements.size;
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    constexpr VkMemoryPropertyFlags lazy = local | VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT;
    out.lazily_allocated =
        transient &&
        find_memory_type_or_none(physical, requirements.memoryTypeBits, lazy) != UINT32_MAX;
    out.memory =
        allocate_memory(physical, device, requirements, out.lazily_allocated ? lazy : local);
    VKT_CHECK(vkBindImageMemory(device, image, out.memory, 0));

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
