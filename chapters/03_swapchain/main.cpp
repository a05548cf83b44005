// Chapter 03: the swapchain and the frame loop. The harness (vkt/frame/harness.hpp)
// opens a window, a headless surface or neither (--offscreen), the instance and
// device (chapters 01, 02), and keeps --frames, --screenshot and --benchmark.
// From the surface to the picture is this file: the swapchain, frame slots,
// acquire, record, submit, present, recreation. The picture: one colour, changing.

#include "vkt/core/memory.hpp"
#include "vkt/core/swapchain.hpp"
#include "vkt/core/swapchain_retirement.hpp"
#include "vkt/frame/harness.hpp"
#include "vkt/resources/readback.hpp"

#include <cmath>
#include <optional>
#include <vector>

namespace {

// [frame-slot]
constexpr uint32_t frames_in_flight = 2;

// One frame in progress: the CPU records into one slot while the GPU works on the other.
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
    bool readable = false;    // --screenshot can copy from the images (TRANSFER_SRC)
    bool drawn_into = false;  // frames are cleared straight into the images, else copied in
};
// [/swapchain-struct]

// [barrier]
// One image barrier: src_stage's work before it ends, and its src_access writes
// are made visible, before dst_stage's dst_access after it; between, the layout changes.
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
    void run();

private:
    void create_swapchain(VkSwapchainKHR old);
    void create_own_image();
    void recreate();
    bool draw_frame(uint64_t index);
    void record(uint32_t slot_index, uint32_t image_index, double time);
    vkt::Destination destination() const;

    vkt::Harness& harness_;
    const bool screenshot_;  // --screenshot: read back what each frame shows
    const vkt::Device& device_;
    std::optional<Swapchain> swapchain_;   // none offscreen
    vkt::SwapchainRetirement retirement_;  // old swapchains, until their presents are over
    vkt::Image own_;  // our own _SRGB image, where frames do not go straight into the swapchain's
    std::vector<FrameSlot> slots_;
    std::optional<uint32_t> last_slot_;  // the slot of the last frame submitted
};

FrameLoop::FrameLoop(vkt::Harness& harness)
    : harness_(harness),
      screenshot_(!harness.options().screenshot.empty()),
      device_(harness.device()),
      retirement_(harness.device(), harness.present_fences()) {
    if (harness.surface()) create_swapchain(VK_NULL_HANDLE);
    create_own_image();

    // [create-slots]
    for (uint32_t i = 0; i < frames_in_flight; ++i) {
        FrameSlot slot;
        // TRANSIENT: the pool's buffer is recorded afresh every frame.
        slot.pool = vkt::create_command_pool(device_, device_.queue_family(),
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
    const VkPhysicalDevice physical = device_.physical();
    VkSurfaceCapabilitiesKHR allows;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &allows));
    // ...the formats it can show, each with a colour space...
    uint32_t n = 0;
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(n);
    VKT_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, formats.data()));
    // ...and how it can take our images to the screen.
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &n, nullptr));
    std::vector<VkPresentModeKHR> modes(n);
    VKT_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &n, modes.data()));
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
    next.mode = vkt::choose_present_mode(modes, harness_.options().benchmark);
    next.readable = screenshot_ && (allows.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
    VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;  // what we will do with the images
    if (next.readable) usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    // Straight in only where the image encodes our linear colour (an _SRGB
    // format) and, for --screenshot, can be read back.
    next.drawn_into = !harness_.options().copy_to_swapchain && next.readable == screenshot_ &&
                      next.format == vkt::render_format_for(next.format);
    // OPAQUE: the window shows our colour, not what lies behind it. A surface
    // without it offers something else, and choose_composite_alpha takes the
    // first it has.
    const VkCompositeAlphaFlagBitsKHR alpha =
        vkt::choose_composite_alpha(allows.supportedCompositeAlpha);
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
        .clipped = next.readable ? VK_FALSE : VK_TRUE,  // hidden pixels: kept if read back
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
    if (swapchain_) retirement_.retire(std::move(*swapchain_));  // kept until its presents end
    swapchain_ = std::move(next);
    // [/create-swapchain]
}

// [own-image]
void FrameLoop::create_own_image() {
    own_ = vkt::Image{};
    if (swapchain_ && swapchain_->drawn_into) return;  // frames go straight into the swapchain's
    // The _SRGB format with the swapchain's byte order, so that a plain copy
    // carries our bytes across unchanged; offscreen, R8G8B8A8_SRGB.
    const VkFormat format =
        swapchain_ ? vkt::render_format_for(swapchain_->format) : VK_FORMAT_R8G8B8A8_SRGB;
    const VkExtent2D extent = swapchain_ ? swapchain_->extent : harness_.wanted_extent();
    // Cleared, then copied from; and COLOR_ATTACHMENT, for the view the helper
    // makes (a view needs a use it can serve; chapter 04 draws through it).
    own_ = vkt::create_image_2d(device_.physical(), device_, format, extent,
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
    // Let the GPU finish the last frames before the screenshot is read.
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
    retirement_.slot_finished(slot_index);     // old swapchains proven free go

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
        retirement_.acquired(image_index, slot_index);
    }
    // Only now that this frame will be submitted: a fence reset before a
    // return above would never be signalled, and the next wait would hang.
    VKT_CHECK(vkResetFences(device_, 1, &done));
    // [/wait-acquire]

    VKT_CHECK(vkResetCommandPool(device_, slot.pool, 0));
    record(slot_index, image_index, harness_.time(index));

    // [submit]
    // Wait for the acquired image at the stage of the first command that
    // writes it (the clear straight in, or the copy); when all is done, signal
    // the image's ready_to_present for the present, the slot's fence for us.
    const VkSemaphoreSubmitInfo wait{
        .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
        .semaphore = slot.image_acquired,
        .stageMask = swapchain_ && swapchain_->drawn_into ? VK_PIPELINE_STAGE_2_CLEAR_BIT
                                                          : VK_PIPELINE_STAGE_2_COPY_BIT,
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
    VKT_CHECK(vkQueueSubmit2(device_.queue(), 1, &submit, slot.done));
    // [/submit]
    last_slot_ = slot_index;
    if (!swapchain_) {  // offscreen: the frame stays in our own image
        harness_.note_presented(own_.extent);
        return true;
    }

    // [present]
    // To the presentation engine, once ready_to_present says the frame is done.
    const VkSwapchainKHR handle = swapchain_->handle;
    const VkSemaphore ready = swapchain_->ready_to_present[image_index];
    const VkPresentInfoKHR present{
        .sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
        .pNext = retirement_.present(image_index),  // a fence that says when it is over
        .waitSemaphoreCount = 1,
        .pWaitSemaphores = &ready,
        .swapchainCount = 1,
        .pSwapchains = &handle,
        .pImageIndices = &image_index,
    };
    const VkResult presented = vkQueuePresentKHR(device_.queue(), &present);
    if (presented != VK_ERROR_OUT_OF_DATE_KHR) vkt::check(presented, "vkQueuePresentKHR");
    harness_.note_presented(swapchain_->extent, retirement_.kept());
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
    const bool drawn_into = swapchain_ && swapchain_->drawn_into;
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
    // written too early: the swapchain image not before the acquire semaphore,
    // which the submit waits for at the CLEAR stage, so the barrier starts
    // there; our own not before the last frame's copy (or read) of it.
    const VkImage cleared = drawn_into ? image : own_.image.get();
    transition(cmd, cleared, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               drawn_into ? VK_PIPELINE_STAGE_2_CLEAR_BIT : VK_PIPELINE_STAGE_2_COPY_BIT,
               VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    const VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, cleared, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &whole);
    // [/clear]
    harness_.gpu_timer().end(cmd, slot_index);  // what follows is presentation, not the frame

    // [copy-in]
    // Where the image that goes on screen stands: layout, and its last write.
    VkImageLayout layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_CLEAR_BIT;
    VkAccessFlags2 access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    if (!drawn_into)  // our image, ready to be copied (or read back) once the clear is done
        transition(cmd, own_.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                   VK_ACCESS_2_TRANSFER_READ_BIT);
    if (swapchain_ && !drawn_into) {
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
    // --screenshot: what this frame shows, into the slot's host-visible buffer
    // (the helper ends with a barrier to the HOST stage). The swapchain image
    // where we may read it, else our own.
    if (screenshot_ && swapchain_ && swapchain_->readable) {
        transition(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage, access,
                   VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::record_readback(device_.physical(), device_, cmd, image, swapchain_->format,
                             swapchain_->extent, slot.readback);
        layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        stage = VK_PIPELINE_STAGE_2_COPY_BIT;
        access = VK_ACCESS_2_NONE;  // after a read, the order is all that matters
    } else if (screenshot_) {
        vkt::record_readback(device_.physical(), device_, cmd, own_.image, own_.format, own_.extent,
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
    // Let the GPU finish the frames in flight (they use our image and the old
    // swapchain's); the presentation engine's hold on it is retirement_'s to watch.
    VKT_CHECK(vkDeviceWaitIdle(device_));
    create_swapchain(swapchain_->handle);  // from the old one, which it retires
    create_own_image();                    // the size may have changed
    harness_.note_recreated(swapchain_->extent, retirement_.kept());
}
// [/recreate]

vkt::Destination FrameLoop::destination() const {
    if (!swapchain_) return {.extent = own_.extent, .format = own_.format};
    return {.swapchain_format = swapchain_->format,
            .present_mode = swapchain_->mode,
            .images = uint32_t(swapchain_->images.size()),
            .drawn_into = swapchain_->drawn_into,
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
