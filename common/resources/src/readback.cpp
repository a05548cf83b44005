#include "vkt/resources/readback.hpp"

#include "vkt/core/check.hpp"

namespace vkt {

void record_readback(VkPhysicalDevice physical, VkDevice device, VkCommandBuffer cmd, VkImage image,
                     VkFormat format, VkExtent2D extent, Readback& readback) {
    const VkDeviceSize size = VkDeviceSize{extent.width} * extent.height * 4;
    if (!readback.buffer.buffer || readback.buffer.size < size)
        readback.buffer = create_buffer(
            physical, device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    readback.extent = extent;
    readback.format = format;

    VkBufferImageCopy region{
        .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
        .imageExtent = {extent.width, extent.height, 1},
    };
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer.buffer,
                           1, &region);
    VkBufferMemoryBarrier2 to_host{
        .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
        .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
        .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
        .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .buffer = readback.buffer.buffer,
        .size = VK_WHOLE_SIZE,
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .bufferMemoryBarrierCount = 1,
        .pBufferMemoryBarriers = &to_host,
    };
    vkCmdPipelineBarrier2(cmd, &dependency);
}

RgbaImage to_rgba(const void* pixels, VkExtent2D extent, VkFormat format) {
    bool bgra = false;
    switch (format) {
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_UNORM:
            bgra = true;
            break;
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_R8G8B8A8_UNORM:
            break;
        default:
            throw Error("to_rgba: not an 8-bit RGBA or BGRA format");
    }
    RgbaImage image{extent.width, extent.height,
                    std::vector<uint8_t>(size_t{extent.width} * extent.height * 4)};
    const auto* bytes = static_cast<const uint8_t*>(pixels);
    for (size_t i = 0; i < image.pixels.size(); i += 4) {
        image.pixels[i + 0] = bytes[i + (bgra ? 2 : 0)];
        image.pixels[i + 1] = bytes[i + 1];
        image.pixels[i + 2] = bytes[i + (bgra ? 0 : 2)];
        image.pixels[i + 3] = 255;
    }
    return image;
}

}  // namespace vkt
