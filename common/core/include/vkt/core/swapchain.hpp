#pragma once
// The swapchain, taught in chapter 03. The choices are pure functions of what
// the surface offers, so the unit tests can check them without a surface.

#include "vkt/core/owned.hpp"

#include <span>
#include <vector>

namespace vkt {

// An 8-bit RGBA or BGRA format in the sRGB colour space: `keep` if the surface
// offers it (a recreated swapchain keeps its format, so the chapter's pipelines
// still match), else _SRGB before _UNORM. Throws Error when there is none.
VkSurfaceFormatKHR choose_surface_format(std::span<const VkSurfaceFormatKHR> available,
                                         VkFormat keep = VK_FORMAT_UNDEFINED);

// The format we render into: the _SRGB format with the swapchain's byte order,
// so a plain copy carries our pixels to the swapchain image unchanged.
VkFormat render_format_for(VkFormat swapchain_format);

// FIFO (vsync, always available) normally; for --benchmark the mode that does
// not wait for the display: IMMEDIATE, then MAILBOX, then FIFO.
VkPresentModeKHR choose_present_mode(std::span<const VkPresentModeKHR> available, bool uncapped);

// The surface's own extent where it has one (a window), else the wanted size
// clamped to what the surface allows (a headless surface).
VkExtent2D choose_extent(const VkSurfaceCapabilitiesKHR& capabilities, VkExtent2D wanted);

// One more image than the minimum, so we never wait for the presentation
// engine to release one, within the surface's maximum (0 means no maximum).
uint32_t choose_image_count(const VkSurfaceCapabilitiesKHR& capabilities);

// OPAQUE where the surface offers it (our alpha is not meant for the
// desktop behind the window), else the first mode it offers.
VkCompositeAlphaFlagBitsKHR choose_composite_alpha(VkCompositeAlphaFlagsKHR supported);

// What the runner asks of a swapchain.
struct SwapchainRequest {
    VkExtent2D extent;                    // used where the surface lets us choose
    bool uncapped = false;                // --benchmark: do not wait for the display
    bool readable = false;                // --screenshot: images may be copied from
    VkFormat keep = VK_FORMAT_UNDEFINED;  // on recreation: the format we had
    bool draw_into = false;               // draw straight into the images where we can
    // The chapter writes its frame with transfer commands (a clear, a copy),
    // so an image it draws straight into needs TRANSFER_DST too.
    bool transfer_into = false;
};

// What a surface offers, as vkGetPhysicalDeviceSurface*KHR report it.
struct SurfaceOffer {
    VkSurfaceCapabilitiesKHR capabilities{};
    std::vector<VkSurfaceFormatKHR> formats;
    std::vector<VkPresentModeKHR> modes;
};
SurfaceOffer query_surface(VkPhysicalDevice physical, VkSurfaceKHR surface);

// Everything vkCreateSwapchainKHR is told that depends on the surface.
struct SwapchainPlan {
    VkSurfaceFormatKHR format{};
    VkExtent2D extent{};
    VkPresentModeKHR present_mode = VK_PRESENT_MODE_FIFO_KHR;
    uint32_t image_count = 0;
    // Only what is needed and offered: COLOR_ATTACHMENT where frames are drawn
    // into the images, else TRANSFER_DST to copy them in; TRANSFER_SRC for
    // --screenshot. The specification promises only COLOR_ATTACHMENT.
    VkImageUsageFlags usage = 0;
    VkSurfaceTransformFlagBitsKHR transform = VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR;
    VkCompositeAlphaFlagBitsKHR composite_alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    bool drawn_into = false;  // frames are drawn straight into the images
    bool readable = false;    // the images may be copied from
    // clipped lets the presentation engine skip pixels hidden behind other
    // windows, which are then undefined when read: only where no image is read.
    bool clipped = true;
};

// The swapchain for `request` on a surface that offers `offer`: a pure
// function, so every case of what a surface may lack is unit-tested. Throws
// Error, saying why, when the picture could reach the images neither by
// drawing nor by copying.
SwapchainPlan plan_swapchain(const SurfaceOffer& offer, const SwapchainRequest& request);

class Swapchain {
public:
    Swapchain(VkPhysicalDevice physical, VkDevice device, VkSurfaceKHR surface,
              const SwapchainRequest& request, VkSwapchainKHR old_swapchain);

    VkSwapchainKHR get() const { return swapchain_; }
    VkFormat format() const { return format_.format; }
    VkExtent2D extent() const { return extent_; }
    VkPresentModeKHR present_mode() const { return present_mode_; }
    // Whether the images can be copied from (asked for, and the surface allows it).
    bool readable() const { return readable_; }
    const std::vector<VkImage>& images() const { return images_; }
    // Whether the images are drawn into directly: asked for, the format is the
    // _SRGB one the chapters render in, and the surface allows it. Then each
    // image has a view for rendering; otherwise frames are copied in.
    bool drawn_into() const { return !views_.empty(); }
    VkImageView view(uint32_t image) const { return views_[image]; }
    // Signalled when the image's frame is rendered; presenting it waits on it.
    // One per swapchain image, not per frame in flight: the presentation engine
    // holds the semaphore until the image comes back from the screen.
    VkSemaphore ready_to_present(uint32_t image) const { return ready_to_present_[image]; }

private:
    SwapchainHandle swapchain_;
    VkSurfaceFormatKHR format_{};
    VkExtent2D extent_{};
    VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
    bool readable_ = false;
    std::vector<VkImage> images_;
    std::vector<Semaphore> ready_to_present_;
    std::vector<ImageView> views_;  // after swapchain_: destroyed before its images go
};

const char* format_name(VkFormat format);
const char* present_mode_name(VkPresentModeKHR mode);

}  // namespace vkt
