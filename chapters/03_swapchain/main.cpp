// Chapter 03: the swapchain and the frame loop.
//
// The first picture on a screen. The harness (vkt/frame/harness.hpp) opens a
// window, or a headless surface, or neither (--offscreen), and the instance
// and device for it, as chapters 01 and 02 taught; it also keeps the command
// line's promises (--frames, --screenshot, --benchmark). Everything between
// the surface and the picture is this file: the swapchain, the frame slots,
// acquiring, recording, submitting and presenting, and recreating the
// swapchain when the window changes. From chapter 04 on, the runner does the
// same, and a chapter only says what to draw.
//
// What each frame shows is the simplest visible thing: the whole image
// cleared to one colour, which changes with time.

#include "vkt/core/memory.hpp"
#include "vkt/core/swapchain.hpp"
#include "vkt/frame/harness.hpp"
#include "vkt/resources/readback.hpp"

#include <bit>
#include <cmath>
#include <optional>
#include <vector>

namespace {

// [frame-slot]
constexpr uint32_t frames_in_flight = 2;

// What one frame in progress needs, so that the CPU can record the next frame
// into one slot while the GPU still works on the other.
struct FrameSlot {
    vkt::CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vkt::Fence done;                // signalled when the GPU has finished the slot's last frame
    vkt::Semaphore image_acquired;  // signalled when the acquired image may be written
    vkt::Readback readback;         // --screenshot: what the slot's last frame presented
};
// [/frame-slot]

// [swapchain-struct]
struct Swapchain {
    vkt::SwapchainHandle handle;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;
    std::vector<VkImage> images;  // the swapchain's own: never destroyed by us
    // One per image: signalled when the image's frame is finished, waited for
    // by its present, and free again only once the image is acquired again.
    std::vector<vkt::Semaphore> ready_to_present;
    bool readable = false;  // --screenshot can copy from the images (TRANSFER_SRC)
    bool direct = false;    // frames are cleared straight into the images, else copied in
};
// [/swapchain-struct]

// [barrier]
// One image barrier: the work of src_stage before it finishes (and its
// src_access writes become visible) before dst_stage's dst_access after it
// begins, and in between the image changes layout.
void transition(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    const VkImageMemoryBarrier2 barrier{
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
        .srcStageMask = src_stage,
        .srcAccessMask = src_access,
        .dstStageMask = dst_stage,
        .dstAccessMask = dst_access,
        .oldLayout = from,
        .newLayout = to,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,  // the image stays with our queue
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1},  // the whole image
    };
    const VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = 1,
        .pImageMemoryBarriers = &barrier,
    };
    vkCmdPipelineBarrier2(cmd, &dependency);
}
// [/barrier]

class FrameLoop {
public:
    explicit FrameLoop(vkt::Harness& harness);
    ~FrameLoop() { vkDeviceWaitIdle(device_); }  // nothing may be destroyed while in use
    FrameLoop(const FrameLoop&) = delete;
    FrameLoop& operator=(const FrameLoop&) = delete;
    void run();

private:
    void create_swapchain(VkSwapchainKHR old);
    void create_own_image();
    void recreate();
    bool draw_frame(uint64_t index);
    void record(uint32_t slot_index, uint32_t image_index, double time);
    vkt::Destination destination() const;

    vkt::Harness& harness_;
    const vkt::Options& options_;
    VkPhysicalDevice physical_;
    VkDevice device_;
    VkQueue queue_;
    std::optional<Swapchain> swapchain_;  // none offscreen
    vkt::Image own_;  // our own _SRGB image, where frames do not go straight into the swapchain's
    std::vector<FrameSlot> slots_;
    std::optional<uint32_t> last_slot_;  // the slot of the last frame submitted
};

FrameLoop::FrameLoop(vkt::Harness& harness)
    : harness_(harness),
      options_(harness.options()),
      physical_(harness.device().physical()),
      device_(harness.device()),
      queue_(harness.device().queue()) {
    if (harness.surface()) create_swapchain(VK_NULL_HANDLE);
    create_own_image();

    // [create-slots]
    for (uint32_t i = 0; i < frames_in_flight; ++i) {
        FrameSlot slot;
        // TRANSIENT: the pool's buffer is recorded afresh every frame.
        slot.pool = vkt::create_command_pool(device_, harness.device().queue_family(),
                                             VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
        const VkCommandBufferAllocateInfo allocate{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
            .commandPool = slot.pool,
            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
            .commandBufferCount = 1,
        };
        VKT_CHECK(vkAllocateCommandBuffers(device_, &allocate, &slot.cmd));
        slot.done = vkt::create_fence(device_, true);  // signalled: the first wait returns at once
        slot.image_acquired = vkt::create_semaphore(device_);
        slots_.push_back(std::move(slot));
    }
    // [/create-slots]
    harness_.announce(destination());
}

void FrameLoop::create_swapchain(VkSwapchainKHR old) {
    // [surface-queries]
    // What the surface allows: sizes, image counts, usages, transforms...
    const VkSurfaceKHR surface = harness_.surface();
    VkSurfaceCapabilitiesKHR allows;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical_, surface, &allows));
    // ...the formats it can show, each with a colour space...
    uint32_t n = 0;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical_, surface, &n, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(n);
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical_, surface, &n, formats.data()));
    // ...and how it can take our images to the screen.
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical_, surface, &n, nullptr));
    std::vector<VkPresentModeKHR> modes(n);
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical_, surface, &n, modes.data()));
    // [/surface-queries]

    // [swapchain-choices]
    // A clear and a copy are transfer writes. Every surface lets us draw into
    // its images (COLOR_ATTACHMENT, chapter 04); transfer writes it may refuse.
    if (!(allows.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw vkt::Error("this surface's images cannot be cleared or copied into");
    Swapchain next;
    const VkSurfaceFormatKHR format = vkt::choose_surface_format(formats);
    next.format = format.format;
    next.extent = vkt::choose_extent(allows, harness_.wanted_extent());
    next.mode = vkt::choose_present_mode(modes, options_.benchmark);
    const bool screenshot = !options_.screenshot.empty();
    next.readable = screenshot && (allows.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;  // what we will do with the images
    if (next.readable) usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    // Straight in only where the image encodes our linear colour (an _SRGB
    // format) and, for --screenshot, can be read back.
    next.direct = !options_.copy_to_swapchain && next.readable == screenshot &&
                  next.format == vkt::render_format_for(next.format);
    // OPAQUE: the window shows our colour, not what lies behind it. A surface
    // without it offers something else; take the first it has.
    VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(allows.supportedCompositeAlpha & alpha))
        alpha = VkCompositeAlphaFlagBitsKHR(1u << std::countr_zero(allows.supportedCompositeAlpha));
    // [/swapchain-choices]

    // [create-swapchain]
    const VkSwapchainCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .surface = surface,
        .minImageCount = vkt::choose_image_count(allows),
        .imageFormat = format.format,
        .imageColorSpace = format.colorSpace,
        .imageExtent = next.extent,
        .imageArrayLayers = 1,
        .imageUsage = usage,
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,  // one queue clears and presents
        .preTransform = allows.currentTransform,        // the screen's rotation, as it is
        .compositeAlpha = alpha,
        .presentMode = next.mode,
        .clipped = VK_TRUE,   // pixels hidden behind other windows need not be kept
        .oldSwapchain = old,  // on recreation: lets the driver hand resources over
    };
    VkSwapchainKHR handle;
    VKT_CHECK(vkCreateSwapchainKHR(device_, &info, nullptr, &handle));
    next.handle = vkt::SwapchainHandle(device_, handle);
    // The images are made by the swapchain; we ask how many, then for them.
    VKT_CHECK(vkGetSwapchainImagesKHR(device_, handle, &n, nullptr));
    next.images.resize(n);
    VKT_CHECK(vkGetSwapchainImagesKHR(device_, handle, &n, next.images.data()));
    for (uint32_t i = 0; i < n; ++i)
        next.ready_to_present.push_back(vkt::create_semaphore(device_));
    swapchain_ = std::move(next);  // the old swapchain, if any, is destroyed here
    // [/create-swapchain]
}

// [own-image]
void FrameLoop::create_own_image() {
    own_ = vkt::Image{};
    if (swapchain_ && swapchain_->direct) return;  // frames go straight into the swapchain's
    // The _SRGB format with the swapchain's byte order, so that a plain copy
    // carries our bytes across unchanged; offscreen, R8G8B8A8_SRGB.
    const VkFormat format =
        swapchain_ ? vkt::render_format_for(swapchain_->format) : VK_FORMAT_R8G8B8A8_SRGB;
    const VkExtent2D extent = swapchain_ ? swapchain_->extent : harness_.wanted_extent();
    // Cleared (TRANSFER_DST), then copied from (TRANSFER_SRC). The helper gives
    // the image a view, which needs a use it can serve: COLOR_ATTACHMENT, which
    // the runner draws into from chapter 04 on.
    own_ = vkt::create_image_2d(physical_, device_, format, extent,
                                VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                VK_IMAGE_ASPECT_COLOR_BIT);
}
// [/own-image]

// [loop]
void FrameLoop::run() {
    for (uint64_t index = 0;;) {
        const vkt::Harness::Next next = harness_.next_frame(index);
        if (next == vkt::Harness::Next::stop) break;  // --frames reached, or the window closed
        if (next == vkt::Harness::Next::restored) recreate();  // back from being minimised
        if (draw_frame(index)) ++index;  // false: the swapchain was recreated instead
    }
    // The GPU may still be working on the last frames: let it finish before
    // the screenshot is read and anything is destroyed.
    VKT_CHECK(vkDeviceWaitIdle(device_));
    harness_.finish(destination(), last_slot_ ? &slots_[*last_slot_].readback : nullptr);
}
// [/loop]

bool FrameLoop::draw_frame(uint64_t index) {
    // [wait-acquire]
    const uint32_t slot_index = uint32_t(index % frames_in_flight);
    FrameSlot& slot = slots_[slot_index];
    // Wait until the GPU has finished the frame that last used this slot (two
    // frames ago): then its command buffer and semaphore are free again.
    VkFence done = slot.done;
    VKT_CHECK(vkWaitForFences(device_, 1, &done, VK_TRUE, UINT64_MAX));
    harness_.gpu_timer().collect(slot_index);  // --benchmark: that frame's GPU time

    // Which image is ours next. image_acquired is signalled once the
    // presentation engine has really let go of it; the call may return sooner.
    uint32_t image_index = 0;
    bool suboptimal = false;
    if (swapchain_) {
        const VkResult acquired =
            vkAcquireNextImageKHR(device_, swapchain_->handle, UINT64_MAX, slot.image_acquired,
                                  VK_NULL_HANDLE, &image_index);
        if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {  // the window changed: nothing acquired
            recreate();
            return false;
        }
        vkt::check(acquired, "vkAcquireNextImageKHR");
        suboptimal = acquired == VK_SUBOPTIMAL_KHR;  // acquired: draw it, then recreate
    }
    // Only now that this frame will be submitted: a fence reset before a
    // return above would never be signalled, and the next wait would hang.
    VKT_CHECK(vkResetFences(device_, 1, &done));
    // [/wait-acquire]

    VKT_CHECK(vkResetCommandPool(device_, slot.pool, 0));
    record(slot_index, image_index, harness_.time(index));

    // [submit]
    // Wait for the acquired image at the stage of the first command that
    // writes it (the clear straight in, or the copy); when every command is
    // done, signal the image's ready_to_present for the present, and the
    // slot's fence for the CPU.
    const bool direct = swapchain_ && swapchain_->direct;
    const VkSemaphoreSubmitInfo wait{
        .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
        .semaphore = slot.image_acquired,
        .stageMask = direct ? VK_PIPELINE_STAGE_2_CLEAR_BIT : VK_PIPELINE_STAGE_2_COPY_BIT,
    };
    const VkSemaphoreSubmitInfo signal{
        .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
        .semaphore = swapchain_ ? swapchain_->ready_to_present[image_index].get() : VK_NULL_HANDLE,
        .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
    };
    const VkCommandBufferSubmitInfo command{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
        .commandBuffer = slot.cmd,
    };
    const VkSubmitInfo2 submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
        .waitSemaphoreInfoCount = swapchain_ ? 1u : 0u,  // offscreen: no semaphores at all
        .pWaitSemaphoreInfos = &wait,
        .commandBufferInfoCount = 1,
        .pCommandBufferInfos = &command,
        .signalSemaphoreInfoCount = swapchain_ ? 1u : 0u,
        .pSignalSemaphoreInfos = &signal,
    };
    VKT_CHECK(vkQueueSubmit2(queue_, 1, &submit, slot.done));
    // [/submit]
    last_slot_ = slot_index;
    if (!swapchain_) {  // offscreen: the frame stays in our own image
        harness_.note_presented(own_.extent);
        return true;
    }

    // [present]
    // Hand the image to the presentation engine, once ready_to_present says
    // its frame is finished.
    const VkSwapchainKHR handle = swapchain_->handle;
    const VkSemaphore ready = swapchain_->ready_to_present[image_index];
    const VkPresentInfoKHR present{
        .sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
        .waitSemaphoreCount = 1,
        .pWaitSemaphores = &ready,
        .swapchainCount = 1,
        .pSwapchains = &handle,
        .pImageIndices = &image_index,
    };
    const VkResult presented = vkQueuePresentKHR(queue_, &present);
    if (presented != VK_ERROR_OUT_OF_DATE_KHR) vkt::check(presented, "vkQueuePresentKHR");
    harness_.note_presented(swapchain_->extent);
    // The frame was drawn either way; the next one needs a new swapchain if the
    // surface has changed, said so, or the window reported a new size.
    if (suboptimal || presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR ||
        harness_.take_resized())
        recreate();
    // [/present]
    return true;
}

void FrameLoop::record(uint32_t slot_index, uint32_t image_index, double time) {
    FrameSlot& slot = slots_[slot_index];
    const VkCommandBuffer cmd = slot.cmd;
    const VkCommandBufferBeginInfo begin{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
    harness_.gpu_timer().begin(cmd, slot_index);
    const bool direct = swapchain_ && swapchain_->direct;
    const VkImage image = swapchain_ ? swapchain_->images[image_index] : VK_NULL_HANDLE;

    // [clear-colour]
    // A slow walk around the colour wheel, in linear RGB (the _SRGB image
    // encodes it for the display). Headless, time is frame index / 60 s.
    const float t = float(time);
    const VkClearColorValue colour{{0.5f + 0.5f * std::sin(t), 0.5f + 0.5f * std::sin(t + 2.094f),
                                    0.5f + 0.5f * std::sin(t + 4.189f), 1.0f}};
    // [/clear-colour]

    // [clear]
    // The image we clear: the swapchain's, or our own. Its old contents do not
    // matter (from UNDEFINED, the driver may drop them), but it must not be
    // written too early. The swapchain image: not before the acquire
    // semaphore, which the submit waits for at the CLEAR stage, so the barrier
    // starts there. Our own: not before the last frame's clear and copy of it.
    const VkImage cleared = direct ? image : own_.image.get();
    transition(cmd, cleared, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               direct ? VK_PIPELINE_STAGE_2_CLEAR_BIT
                      : VK_PIPELINE_STAGE_2_CLEAR_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
               direct ? VK_ACCESS_2_NONE : VK_ACCESS_2_TRANSFER_WRITE_BIT,
               VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, cleared, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &whole);
    // [/clear]
    harness_.gpu_timer().end(cmd, slot_index);  // what follows is presentation, not the frame

    // [copy-in]
    // Where the image that goes on screen stands now: its layout, and the
    // stage and access of its last write.
    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    VkAccessFlags2 access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    const bool screenshot = !options_.screenshot.empty();
    if (!direct && (swapchain_ || screenshot))  // our image is copied from: clear first
        transition(cmd, own_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_TRANSFER_READ_BIT);
    if (swapchain_ && !direct) {
        // The swapchain image, after the acquire semaphore (waited for at COPY).
        transition(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkImageCopy region{
            .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
            .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
            .extent = {own_.extent.width, own_.extent.height, 1},
        };
        vkCmdCopyImage(cmd, own_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        stage = VK_PIPELINE_STAGE_2_COPY_BIT;
    }
    // [/copy-in]

    // [read-back]
    // --screenshot: copy what this frame shows into the slot's host-visible
    // buffer (the helper ends with a barrier to the HOST stage). The
    // swapchain image where we may read it, else our own.
    if (screenshot && swapchain_ && swapchain_->readable) {
        transition(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage, access,
                   VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::record_readback(physical_, device_, cmd, image, swapchain_->format, swapchain_->extent,
                             slot.readback);
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        stage = VK_PIPELINE_STAGE_2_COPY_BIT;
        access = VK_ACCESS_2_NONE;  // after a read, the order is all that matters
    } else if (screenshot) {
        vkt::record_readback(physical_, device_, cmd, own_.image, own_.format, own_.extent,
                             slot.readback);
    }
    // [/read-back]

    // [to-present]
    // The layout presentation needs. Nothing after it in this command buffer
    // touches the image (NONE): the present waits for ready_to_present, which
    // the submit signals once every command is done.
    if (swapchain_)
        transition(cmd, image, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, stage, access,
                   VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    // [/to-present]
    VKT_CHECK(vkEndCommandBuffer(cmd));
}

// [recreate]
void FrameLoop::recreate() {
    // A minimised window may be 0x0, and no swapchain can be: wait it out.
    if (!harness_.wait_while_minimised()) return;  // closed meanwhile
    harness_.take_resized();                       // this answers every resize so far
    // Simple and safe: let the GPU finish everything that uses the old images.
    VKT_CHECK(vkDeviceWaitIdle(device_));
    create_swapchain(swapchain_->handle);  // from the old one, which then goes
    create_own_image();                    // the size may have changed
    harness_.note_recreated(swapchain_->extent);
}
// [/recreate]

vkt::Destination FrameLoop::destination() const {
    if (!swapchain_) return {.extent = own_.extent, .format = own_.format};
    return {.swapchain_format = swapchain_->format,
            .present_mode = swapchain_->mode,
            .images = uint32_t(swapchain_->images.size()),
            .drawn_into = swapchain_->direct,
            .extent = swapchain_->extent,
            .format = vkt::render_format_for(swapchain_->format)};
}

}  // namespace

// [main]
int main(int argc, char** argv) {
    return vkt::run_in_harness(argc, argv, {.name = "03_swapchain", .title = "03 - swapchain"},
                               frames_in_flight,
                               [](vkt::Harness& harness) { FrameLoop(harness).run(); });
}
// [/main]
