#include "vkt/core/swapchain.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>

namespace vkt {

// [choose-format]
namespace {

// The formats we take, in pairs of one byte order: the _SRGB one we draw
// into, and its _UNORM sibling with the same bytes.
struct FormatPair {
    VkFormat srgb, unorm;
};
constexpr FormatPair format_pairs[] = {
    {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_B8G8R8A8_UNORM},
    {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R8G8B8A8_UNORM},
};

const FormatPair* pair_of(VkFormat format) {
    for (const FormatPair& pair : format_pairs)
        if (format == pair.srgb || format == pair.unorm) return &pair;
    return nullptr;
}

}  // namespace

VkSurfaceFormatKHR choose_surface_format(std::span<const VkSurfaceFormatKHR> available,
                                         VkFormat keep) {
    // Any of these will do. _SRGB first: we can draw straight into it. A
    // _UNORM image gets its bytes copied in from an _SRGB image of our own
    // (see render_format_for); headless surfaces offer only _UNORM formats.
    // When recreating, `keep` and then its sibling with the same byte order come
    // first: the chapter's pipelines were made for that byte order.
    const FormatPair* kept = pair_of(keep);
    const VkFormat sibling = !kept                ? VK_FORMAT_UNDEFINED
                             : keep == kept->srgb ? kept->unorm
                                                  : kept->srgb;
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
    if (const FormatPair* pair = pair_of(swapchain_format)) return pair->srgb;
    throw Error(std::string("no render format for swapchain format ") +
                format_name(swapchain_format));
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

VkCompositeAlphaFlagBitsKHR choose_composite_alpha(VkCompositeAlphaFlagsKHR supported) {
    if (supported & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR) return VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    // The lowest bit set: a surface must offer at least one mode.
    return VkCompositeAlphaFlagBitsKHR(supported & (~supported + 1));
}

SurfaceOffer query_surface(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    SurfaceOffer offer;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &offer.capabilities));
    uint32_t count = 0;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
    offer.formats.resize(count);
    VKT_CHECK(
        vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, offer.formats.data()));
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
    offer.modes.resize(count);
    VKT_CHECK(
        vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, offer.modes.data()));
    return offer;
}

// [plan-swapchain]
SwapchainPlan plan_swapchain(const SurfaceOffer& offer, const SwapchainRequest& request) {
    const VkSurfaceCapabilitiesKHR& capabilities = offer.capabilities;
    const VkImageUsageFlags offered = capabilities.supportedUsageFlags;
    SwapchainPlan plan;
    plan.format = choose_surface_format(offer.formats, request.keep);
    plan.extent = choose_extent(capabilities, request.extent);
    plan.present_mode = choose_present_mode(offer.modes, request.uncapped);
    plan.image_count = choose_image_count(capabilities);
    plan.transform = capabilities.currentTransform;
    plan.composite_alpha = choose_composite_alpha(capabilities.supportedCompositeAlpha);

    // --screenshot reads back the image we present, where the surface allows it.
    plan.readable = request.readable && (offered & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    const bool copy_in = offered & VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    // Drawing straight into the images saves a full-screen copy per frame. It
    // needs the _SRGB format the chapters' pipelines are made for (a _UNORM
    // image would take our linear colours as already encoded), images we can
    // read back where --screenshot wants them, and TRANSFER_DST for a chapter
    // that clears or copies into its frame.
    const bool srgb = plan.format.format == render_format_for(plan.format.format);
    plan.drawn_into = request.draw_into && srgb &&
                      (offered & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) &&
                      plan.readable == request.readable && (!request.transfer_into || copy_in);
    if (!plan.drawn_into && !copy_in) {
        const char* why =
            !request.draw_into ? "--copy-to-swapchain asks to copy"
            : !srgb            ? "its format is not an _SRGB one"
            : request.transfer_into
                ? "this chapter writes its frames with transfer commands"
                : "--screenshot needs them readable (TRANSFER_SRC), which they are not";
        throw Error(std::string("the surface's images cannot be copied into (no TRANSFER_DST "
                                "usage) and frames cannot be drawn into them: ") +
                    why + " (" + format_name(plan.format.format) + ")");
    }
    plan.usage = plan.drawn_into ? VkImageUsageFlags{VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT}
                                 : VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_DST_BIT};
    if (plan.drawn_into && request.transfer_into) plan.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (plan.readable) plan.usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    plan.clipped = !plan.readable;
    return plan;
}
// [/plan-swapchain]

Swapchain::Swapchain(VkPhysicalDevice physical, VkDevice device, VkSurfaceKHR surface,
                     const SwapchainRequest& request, VkSwapchainKHR old_swapchain) {
    // What the surface offers decides every setting (plan_swapchain, above).
    const SwapchainPlan plan = plan_swapchain(query_surface(physical, surface), request);
    format_ = plan.format;
    extent_ = plan.extent;
    present_mode_ = plan.present_mode;
    readable_ = plan.readable;
    const bool drawn_into = plan.drawn_into;

    VkSwapchainCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .surface = surface,
        .minImageCount = plan.image_count,
        .imageFormat = format_.format,
        .imageColorSpace = format_.colorSpace,
        .imageExtent = extent_,
        .imageArrayLayers = 1,
        .imageUsage = plan.usage,
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,  // one queue draws and presents
        .preTransform = plan.transform,
        .compositeAlpha = plan.composite_alpha,
        .presentMode = present_mode_,
        .clipped = plan.clipped ? VK_TRUE : VK_FALSE,
        .oldSwapchain = old_swapchain,  // lets the driver hand resources over on resize
    };
    VkSwapchainKHR swapchain;
    VKT_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain));
    swapchain_ = SwapchainHandle(device, swapchain);

    uint32_t count = 0;
    VKT_CHECK(vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr));
    images_.resize(count);
    VKT_CHECK(vkGetSwapchainImagesKHR(device, swapchain, &count, images_.data()));
    for (uint32_t i = 0; i < count; ++i) ready_to_present_.push_back(create_semaphore(device));

    // [swapchain-views]
    // To render into an image, a pipeline sees it through a view: which
    // format, which mip levels and layers. Ours is the whole image as it is.
    if (drawn_into) {
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
