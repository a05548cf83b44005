// The runner's swapchain and colour target (chapter 03): a swapchain where the
// harness has a surface (a window or a headless one), and our own image where
// frames cannot go straight into the swapchain's, or where there is none
// (offscreen). The frame loop that draws into them is runner.cpp;
// chapter_run.hpp says how the two meet.

#include "chapter_run.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/memory.hpp"

#include <cstdio>

namespace vkt::detail {

void ChapterRun::create_swapchain() {
    VkExtent2D extent = harness_.wanted_extent();
    if (harness_.surface()) {
        swapchain_ = std::make_unique<Swapchain>(
            device_.physical(), device_, harness_.surface(),
            SwapchainRequest{.extent = extent,
                             .uncapped = options_.benchmark,
                             .readable = !options_.screenshot.empty(),
                             .draw_into = !options_.copy_to_swapchain,
                             .transfer_into = spec_.transfers_into_target},
            VK_NULL_HANDLE);
        extent = swapchain_->extent();
    }
    create_target(extent);
}

namespace {

// [storage-view]
// Our target with a second view, for a chapter that writes its pixels from a
// compute shader (ChapterSpec::storage_target). Most devices cannot store to
// an _SRGB format, but the bytes a compute pass writes are sRGB-encoded
// already: it stores them through a view in the _UNORM format with the same
// byte order, where that format can be a storage image (R8G8B8A8_UNORM can
// on every device; B8G8R8A8_UNORM not on all). VK_FORMAT_UNDEFINED: no view.
VkFormat storage_format_for(VkPhysicalDevice physical, VkFormat format, VkImageUsageFlags usage) {
    const VkFormat unorm = format == VK_FORMAT_B8G8R8A8_SRGB   ? VK_FORMAT_B8G8R8A8_UNORM
                           : format == VK_FORMAT_R8G8B8A8_SRGB ? VK_FORMAT_R8G8B8A8_UNORM
                                                               : VK_FORMAT_UNDEFINED;
    if (unorm == VK_FORMAT_UNDEFINED) return unorm;
    VkFormatProperties features{};
    vkGetPhysicalDeviceFormatProperties(physical, unorm, &features);
    if (!(features.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT))
        return VK_FORMAT_UNDEFINED;
    VkImageFormatProperties limits{};
    const VkResult result = vkGetPhysicalDeviceImageFormatProperties(
        physical, format, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
        usage | VK_IMAGE_USAGE_STORAGE_BIT,
        VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT | VK_IMAGE_CREATE_EXTENDED_USAGE_BIT, &limits);
    return result == VK_SUCCESS ? unorm : VK_FORMAT_UNDEFINED;
}

// MUTABLE_FORMAT lets views have another format of the same texel size (the
// format list names the two, so a driver may still compress the image);
// EXTENDED_USAGE lets the image have a usage, STORAGE, that only one of its
// views' formats supports. Each view then says which usages are its own.
VkImageView create_view(VkDevice device, VkImage image, VkFormat format, VkImageUsageFlags usage) {
    const VkImageViewUsageCreateInfo view_usage{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO, .usage = usage};
    const VkImageViewCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .pNext = &view_usage,
        .image = image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D,
        .format = format,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1},
    };
    VkImageView view;
    VKT_CHECK(vkCreateImageView(device, &info, nullptr, &view));
    return view;
}
// [/storage-view]

Image create_storage_target(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                            VkFormat storage_format, VkExtent2D extent, VkImageUsageFlags usage,
                            ImageView& storage_view) {
    const VkFormat formats[] = {format, storage_format};
    const VkImageFormatListCreateInfo format_list{
        .sType = VK_STRUCTURE_TYPE_IMAGE_FORMAT_LIST_CREATE_INFO,
        .viewFormatCount = 2,
        .pViewFormats = formats,
    };
    const VkImageCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .pNext = &format_list,
        .flags = VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT | VK_IMAGE_CREATE_EXTENDED_USAGE_BIT,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = format,
        .extent = {extent.width, extent.height, 1},
        .mipLevels = 1,
        .arrayLayers = 1,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .tiling = VK_IMAGE_TILING_OPTIMAL,
        .usage = usage | VK_IMAGE_USAGE_STORAGE_BIT,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
    };
    Image out;
    out.format = format;
    out.extent = extent;
    VkImage image;
    VKT_CHECK(vkCreateImage(device, &info, nullptr, &image));
    out.image = ImageHandle(device, image);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, image, &requirements);
    out.memory =
        allocate_memory(physical, device, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VKT_CHECK(vkBindImageMemory(device, image, out.memory, 0));
    out.view = ImageView(device, create_view(device, image, format, usage));
    storage_view =
        ImageView(device, create_view(device, image, storage_format, VK_IMAGE_USAGE_STORAGE_BIT));
    return out;
}

}  // namespace

void ChapterRun::create_target(VkExtent2D extent) {
    VkFormat format =
        swapchain_ ? render_format_for(swapchain_->format()) : VK_FORMAT_R8G8B8A8_SRGB;
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                    VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (spec_.storage_target)
        storage_format_ = storage_format_for(device_.physical(), format, usage);
    own_storage_.clear();  // before the images they view
    own_.clear();
    format_ = format;
    extent_ = extent;
    if (drawn_into()) return;  // frames go straight into the swapchain's images
    for (uint32_t slot = 0; slot < frames_in_flight; ++slot) {
        if (storage_format_ != VK_FORMAT_UNDEFINED)
            own_.push_back(create_storage_target(device_.physical(), device_, format,
                                                 storage_format_, extent, usage,
                                                 own_storage_.emplace_back()));
        else
            own_.push_back(create_image_2d(device_.physical(), device_, format, extent, usage,
                                           VK_IMAGE_ASPECT_COLOR_BIT));
    }
}

void ChapterRun::recreate_swapchain() {
    if (!harness_.wait_while_minimised()) return;  // a 0x0 swapchain cannot exist
    harness_.take_resized();                       // this recreation answers any resize so far
    // The frames in flight use our target and the old images' views: let the
    // GPU finish them. (The presentation engine's use of the old swapchain is
    // not queue work, so this does not cover it: retirement_ does.)
    VKT_CHECK(vkDeviceWaitIdle(device_));
    auto next = std::make_unique<Swapchain>(
        device_.physical(), device_, harness_.surface(),
        SwapchainRequest{.extent = harness_.window() ? harness_.wanted_extent() : extent_,
                         .uncapped = options_.benchmark,
                         .readable = !options_.screenshot.empty(),
                         .keep = swapchain_->format(),
                         .draw_into = !options_.copy_to_swapchain,
                         .transfer_into = spec_.transfers_into_target},
        swapchain_->get());
    retirement_.retire(std::move(swapchain_));  // kept until its presents are over
    swapchain_ = std::move(next);
    // The chapter's pipelines were made for our target's format; it must not change.
    if (render_format_for(swapchain_->format()) != format_)
        throw Error(std::string("the surface no longer offers a format with the byte order of ") +
                    format_name(format_));
    VkExtent2D extent = swapchain_->extent();
    harness_.note_recreated(extent, retirement_.kept());
    const bool resized = extent.width != extent_.width || extent.height != extent_.height;
    // A new size needs a new target; so does a swapchain we can no longer draw
    // into (or now can), e.g. one that came back in the _UNORM format.
    if (resized || swapchain_->drawn_into() == !own_.empty()) create_target(extent);
    if (resized) renderer_->resize(extent);
}

}  // namespace vkt::detail
