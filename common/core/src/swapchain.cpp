#include "vkt/core/swapchain.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>

namespace vkt {

// [choose-format]
VkSurfaceFormatKHR choose_surface_format(std::span<const VkSurfaceFormatKHR> available,
                                         VkFormat keep) {
    // Any of these will do. _SRGB first: we can draw straight into it. A
    // _UNORM image gets its bytes copied in from an _SRGB image of our own
    // (see render_format_for); headless surfaces offer only _UNORM formats.
    // When recreating, `keep` and then its sibling with the same byte order come
    // first: the chapter's pipelines were made for that byte order.
    VkFormat sibling = VK_FORMAT_UNDEFINED;
    switch (keep) {
        case VK_FORMAT_B8G8R8A8_SRGB:
            sibling = VK_FORMAT_B8G8R8A8_UNORM;
            break;
        case VK_FORMAT_B8G8R8A8_UNORM:
            sibling = VK_FORMAT_B8G8R8A8_SRGB;
            break;
        case VK_FORMAT_R8G8B8A8_SRGB:
            sibling = VK_FORMAT_R8G8B8A8_UNORM;
            break;
        case VK_FORMAT_R8G8B8A8_UNORM:
            sibling = VK_FORMAT_R8G8B8A8_SRGB;
            break;
        default:
            break;
    }
    const VkFormat preferred[] = {keep,
                                  sibling,
                                  VK_FORMAT_B8G8R8A8_SRGB,
                                  VK_FORMAT_R8G8B8A8_SRGB,
                                  VK_FORMAT_B8G8R8A8_UNORM,
                                  VK_FORMAT_R8G8B8A8_UNORM};
    for (VkFormat format : preferred)
        for (const auto& candidate : available)
            if (candidate.format == format &&
                candidate.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
                return candidate;
    throw Error("the surface offers no 8-bit RGBA or BGRA format in the sRGB colour space");
}

VkFormat render_format_for(VkFormat swapchain_format) {
    switch (swapchain_format) {
        case VK_FORMAT_B8G8R8A8_SRGB:
        case VK_FORMAT_B8G8R8A8_UNORM:
            return VK_FORMAT_B8G8R8A8_SRGB;
        case VK_FORMAT_R8G8B8A8_SRGB:
        case VK_FORMAT_R8G8B8A8_UNORM:
            return VK_FORMAT_R8G8B8A8_SRGB;
        default:
            throw Error(std::string("no render format for swapchain format ") +
                        format_name(swapchain_format));
    }
}
// [/choose-format]

VkPresentModeKHR choose_present_mode(std::span<const VkPresentModeKHR> available, bool uncapped) {
    if (uncapped)
        for (VkPresentModeKHR mode : {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR})
            if (std::find(available.begin(), available.end(), mode) != available.end()) return mode;
    return VK_PRESENT_MODE_FIFO_KHR;  // the only mode every driver must offer
}

VkExtent2D choose_extent(const VkSurfaceCapabilitiesKHR& capabilities, VkExtent2D wanted) {
    if (capabilities.currentExtent.width != UINT32_MAX) return capabilities.currentExtent;
    return {std::clamp(wanted.width, capabilities.minImageExtent.width,
                       capabilities.maxImageExtent.width),
            std::clamp(wanted.height, capabilities.minImageExtent.height,
                       capabilities.maxImageExtent.height)};
}

uint32_t choose_image_count(const VkSurfaceCapabilitiesKHR& capabilities) {
    uint32_t count = capabilities.minImageCount + 1;
    if (capabilities.maxImageCount > 0) count = std::min(count, capabilities.maxImageCount);
    return count;
}

Swapchain::Swapchain(VkPhysicalDevice physical, VkDevice device, VkSurfaceKHR surface,
                     const SwapchainRequest& request, VkSwapchainKHR old_swapchain) {
    VkSurfaceCapabilitiesKHR capabilities;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &capabilities));

    uint32_t count = 0;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()));

    // Frames are copied or cleared into the images (TRANSFER_DST) in any case:
    // when we cannot draw into them, and by chapters that copy their picture in.
    if (!(capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw Error("the surface's images cannot be copied into (no TRANSFER_DST usage)");

    format_ = choose_surface_format(formats, request.keep);
    extent_ = choose_extent(capabilities, request.extent);
    present_mode_ = choose_present_mode(modes, request.uncapped);
    // --screenshot reads back the image we present, where the surface allows it.
    readable_ =
        request.readable && (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    // Drawing straight into the images saves a full-screen copy per frame. It
    // needs the _SRGB format the chapters' pipelines are made for (a _UNORM
    // image would take our linear colours as already encoded), and, for
    // --screenshot, images we can read back.
    const bool drawable =
        request.drawable && format_.format == render_format_for(format_.format) &&
        (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) &&
        readable_ == request.readable;

    VkSwapchainCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .surface = surface,
        .minImageCount = choose_image_count(capabilities),
        .imageFormat = format_.format,
        .imageColorSpace = format_.colorSpace,
        .imageExtent = extent_,
        .imageArrayLayers = 1,
        .imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                      (readable_ ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT}
                                 : VkImageUsageFlags{0}) |
                      (drawable ? VkImageUsageFlags{VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT}
                                : VkImageUsageFlags{0}),
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,  // one queue draws and presents
        .preTransform = capabilities.currentTransform,
        .compositeAlpha = (capabilities.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(capabilities.supportedCompositeAlpha &
                                                            -capabilities.supportedCompositeAlpha),
        .presentMode = present_mode_,
        .clipped = VK_TRUE,
        .oldSwapchain = old_swapchain,  // lets the driver hand resources over on resize
    };
    VkSwapchainKHR swapchain;
    VKT_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain));
    swapchain_ = SwapchainHandle(device, swapchain);

    VKT_CHECK(vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr));
    images_.resize(count);
    VKT_CHECK(vkGetSwapchainImagesKHR(device, swapchain, &count, images_.data()));
    for (uint32_t i = 0; i < count; ++i) ready_to_present_.push_back(create_semaphore(device));

    // [swapchain-views]
    // To render into an image, a pipeline sees it through a view: which
    // format, which mip levels and layers. Ours is the whole image as it is.
    if (drawable) {
        for (VkImage image : images_) {
            VkImageViewCreateInfo view_info{
                .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                .image = image,
                .viewType = VK_IMAGE_VIEW_TYPE_2D,
                .format = format_.format,
                .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1},
            };
            VkImageView view;
            VKT_CHECK(vkCreateImageView(device, &view_info, nullptr, &view));
            views_.emplace_back(device, view);
        }
    }
    // [/swapchain-views]
}

const char* format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_B8G8R8A8_SRGB:
            return "B8G8R8A8_SRGB";
        case VK_FORMAT_B8G8R8A8_UNORM:
            return "B8G8R8A8_UNORM";
        case VK_FORMAT_R8G8B8A8_SRGB:
            return "R8G8B8A8_SRGB";
        case VK_FORMAT_R8G8B8A8_UNORM:
            return "R8G8B8A8_UNORM";
        default:
            return "another format";
    }
}

const char* present_mode_name(VkPresentModeKHR mode) {
    switch (mode) {
        case VK_PRESENT_MODE_IMMEDIATE_KHR:
            return "IMMEDIATE";
        case VK_PRESENT_MODE_MAILBOX_KHR:
            return "MAILBOX";
        case VK_PRESENT_MODE_FIFO_KHR:
            return "FIFO";
        case VK_PRESENT_MODE_FIFO_RELAXED_KHR:
            return "FIFO_RELAXED";
        default:
            return "another mode";
    }
}

}  // namespace vkt
