#include "vkt/resources/depth.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"

#include <array>
#include <string>

namespace vkt {

std::span<const VkFormat> depth_format_candidates() {
    static constexpr std::array<VkFormat, 4> formats{
        VK_FORMAT_D32_SFLOAT,
        VK_FORMAT_D32_SFLOAT_S8_UINT,
        VK_FORMAT_D24_UNORM_S8_UINT,
        VK_FORMAT_D16_UNORM,
    };
    return formats;
}

VkFormat choose_depth_format(VkPhysicalDevice physical) {
    std::string tried;
    for (VkFormat format : depth_format_candidates()) {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(physical, format, &properties);
        if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
            return format;
        tried += tried.empty() ? "" : ", ";
        tried += depth_format_name(format);
    }
    throw Error("no depth format can be a depth attachment on this device (tried " + tried + ")");
}

const char* depth_format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D32_SFLOAT:
            return "VK_FORMAT_D32_SFLOAT";
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return "VK_FORMAT_D32_SFLOAT_S8_UINT";
        case VK_FORMAT_D24_UNORM_S8_UINT:
            return "VK_FORMAT_D24_UNORM_S8_UINT";
        case VK_FORMAT_D16_UNORM:
            return "VK_FORMAT_D16_UNORM";
        default:
            return "another format";
    }
}

bool has_stencil(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT_S8_UINT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
           format == VK_FORMAT_D16_UNORM_S8_UINT || format == VK_FORMAT_S8_UINT;
}

Image create_depth_image(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                         VkExtent2D extent, VkSampleCountFlagBits samples, bool transient) {
    return create_attachment_image(physical, device, format, extent,
                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                   VK_IMAGE_ASPECT_DEPTH_BIT, samples, transient);
}

void begin_depth_frame(VkCommandBuffer cmd, VkImage depth_image) {
    // Both fragment-test stages: depth is read and written in EARLY (or LATE,
    // where a shader writes gl_FragDepth), and the clear of loadOp counts as a
    // write in EARLY. Waiting for the last frame's writes before the layout
    // change (itself a write) is what synchronisation validation checks.
    constexpr VkPipelineStageFlags2 tests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    image_barrier(cmd, depth_image, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, tests,
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, tests,
                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                  VK_IMAGE_ASPECT_DEPTH_BIT);
}

}  // namespace vkt
