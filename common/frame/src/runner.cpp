// The runner's frame loop: chapter 03's loop as a helper, for chapters 04 on.
// The swapchain and our colour target are presentation.cpp's; the window or
// surface, the device, the frame count, --screenshot and --benchmark are the
// harness's (harness.cpp).

#include "vkt/frame/runner.hpp"

#include "chapter_run.hpp"
#include "guarded.hpp"

#include "vkt/core/barrier.hpp"

#include <cstdio>
#include <filesystem>

namespace vkt {
namespace detail {

ChapterRun::ChapterRun(Harness& harness)
    : harness_(harness),
      options_(harness.options()),
      spec_(harness.spec()),
      device_(harness.device()),
      retirement_(harness.device(), harness.present_fences()) {
    create_swapchain();  // and our colour target

    for (uint32_t i = 0; i < frames_in_flight; ++i) {
        FrameSlot slot{
            .pool = create_command_pool(device_, device_.queue_family(),
                                        VK_COMMAND_POOL_CREATE_TRANSIENT_BIT),
            .done = create_fence(device_, true),  // signalled: the first wait returns at once
            .image_acquired = create_semaphore(device_),
        };
        VkCommandBufferAllocateInfo allocate{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
            .commandPool = slot.pool,
            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
            .commandBufferCount = 1,
        };
        VKT_CHECK(vkAllocateCommandBuffers(device_, &allocate, &slot.cmd));
        slots_.push_back(std::move(slot));
    }
    harness_.announce(destination());
}

Destination ChapterRun::destination() const {
    Destination where{.extent = extent_, .format = format_};
    if (swapchain_) {
        where.swapchain_format = swapchain_->format();
        where.present_mode = swapchain_->present_mode();
        where.images = uint32_t(swapchain_->images().size());
        where.drawn_into = swapchain_->drawn_into();
    }
    return where;
}

void ChapterRun::run(const RendererFactory& factory) {
    const Context context{
        .options = options_,
        .chapter = spec_.name,
        .instance = harness_.instance(),
        .physical = device_.physical(),
        .device = device_,
        .queue = device_.queue(),
        .queue_family = device_.queue_family(),
        .compute_queue = device_.compute_queue(),
        .compute_family = device_.compute_family(),
        .color_format = format_,
        .storage_format = storage_format_,
        .extent = extent_,
        .frames_in_flight = frames_in_flight,
        .properties = device_.properties(),
        .hidden = harness_.hidden(),
        .features = device_.features(),
    };
    renderer_ = factory(context);

    Window* window = harness_.window();
    // The overlay where the reader can use it (a window run without
    // --frames), or where --overlay on asks for it: a headless picture of it.
    if (harness_.overlay()) {
        if (overlay_available())
            overlay_ = std::make_unique<Overlay>(context);
        else if (harness_.overlay_choice() == "on")
            throw Error("--overlay on: this build has no Dear ImGui (libimgui-dev), so no overlay");
        else
            std::fprintf(stderr, "%s: no overlay: this build has no Dear ImGui\n",
                         spec_.name.c_str());
    }
    for (uint64_t index = 0;;) {
        const Harness::Next next = harness_.next_frame(index);
        if (next == Harness::Next::stop) break;
        if (next == Harness::Next::restored) {
            recreate_swapchain();  // the surface may have changed while minimised
            continue;
        }
        // Input only in an open-ended window run: with --frames, as headless,
        // every frame sees an empty snapshot, so the run is reproducible.
        const Input input = window && !harness_.fixed_step() ? window->take_input() : Input{};
        if (!draw_frame(index, harness_.time(index), input)) {
            // The swapchain was recreated instead: try again, with this input
            // given back, since no frame saw it (a key tapped now still counts).
            if (window) window->give_back_input(input);
            continue;
        }
        ++index;
    }

    VKT_CHECK(vkDeviceWaitIdle(device_));
    harness_.finish(destination(), last_slot_ ? &slots_[*last_slot_].readback : nullptr);
    if (last_slot_) renderer_->verify();  // checks on the last frame, outside the loop
    renderer_.reset();
}

bool ChapterRun::draw_frame(uint64_t index, double time, const Input& input) {
    const uint32_t slot_index = uint32_t(index % frames_in_flight);
    FrameSlot& slot = slots_[slot_index];

    // Wait until the GPU is done with this slot's previous frame (two frames ago),
    // so its command buffer and semaphore can be used again.
    VkFence done = slot.done;
    VKT_CHECK(vkWaitForFences(device_, 1, &done, VK_TRUE, UINT64_MAX));
    harness_.gpu_timer().collect(slot_index);
    retirement_.slot_finished(slot_index);  // old swapchains whose presents are over go now

    uint32_t image_index = 0;
    bool suboptimal = false;  // an image was acquired, but recreate after this frame
    if (swapchain_) {
        VkResult result = vkAcquireNextImageKHR(device_, swapchain_->get(), UINT64_MAX,
                                                slot.image_acquired, VK_NULL_HANDLE, &image_index);
        if (result == VK_ERROR_OUT_OF_DATE_KHR) {  // the window changed: nothing was acquired
            recreate_swapchain();
            return false;
        }
        check(result, "vkAcquireNextImageKHR");
        suboptimal = result == VK_SUBOPTIMAL_KHR;
        retirement_.acquired(image_index, slot_index);
    }
    VKT_CHECK(vkResetFences(device_, 1, &done));  // only now that we will submit

    // The chapter draws into the acquired swapchain image itself where it can,
    // else into our own image, which record() then copies into the swapchain's.
    const bool straight = drawn_into();
    if (overlay_)  // the reader's changes, before the frame that shows them
        overlay_->build(input, extent_, time,
                        [&](OverlayPanel& panel) { renderer_->overlay(panel); });
    VKT_CHECK(vkResetCommandPool(device_, slot.pool, 0));
    const Frame frame{
        .cmd = slot.cmd,
        .target = straight ? swapchain_->images()[image_index] : own_[slot_index].image.get(),
        .target_view = straight ? swapchain_->view(image_index) : own_[slot_index].view.get(),
        .target_storage =
            straight || own_storage_.empty() ? VK_NULL_HANDLE : own_storage_[slot_index].get(),
        .extent = extent_,
        .target_layout = spec_.target_layout,
        .target_ready = target_ready(),
        .index = index,
        .time = time,
        .slot = slot_index,
        .input = input,
        .timer = harness_.gpu_timer() ? &harness_.gpu_timer() : nullptr};
    record(slot, image_index, frame);

    // Submit: wait for the acquired image before the first write to it (the
    // chapter's drawing, or our copy), signal the image's own ready_to_present
    // semaphore, and the slot's fence for the CPU; and whatever the chapter
    // asks besides (its own submits' semaphores, chapter 29).
    FrameSemaphores sync = renderer_->semaphores(frame);
    if (swapchain_) {
        sync.wait.push_back({
            .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
            .semaphore = slot.image_acquired,
            .stageMask = acquire_wait_stage(),
        });
        sync.signal.push_back({
            .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
            .semaphore = swapchain_->ready_to_present(image_index),
            .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
        });
    }
    VkCommandBufferSubmitInfo command{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
        .commandBuffer = slot.cmd,
    };
    VkSubmitInfo2 submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
        .waitSemaphoreInfoCount = uint32_t(sync.wait.size()),
        .pWaitSemaphoreInfos = sync.wait.data(),
        .commandBufferInfoCount = 1,
        .pCommandBufferInfos = &command,
        .signalSemaphoreInfoCount = uint32_t(sync.signal.size()),
        .pSignalSemaphoreInfos = sync.signal.data(),
    };
    VKT_CHECK(vkQueueSubmit2(device_.queue(), 1, &submit, slot.done));
    last_slot_ = slot_index;
    if (!swapchain_) harness_.note_presented(extent_);

    if (swapchain_) {
        VkSwapchainKHR swapchain = swapchain_->get();
        VkSemaphore ready = swapchain_->ready_to_present(image_index);
        VkPresentInfoKHR present{
            .sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
            .pNext = retirement_.present(image_index),  // a present fence, where offered
            .waitSemaphoreCount = 1,
            .pWaitSemaphores = &ready,
            .swapchainCount = 1,
            .pSwapchains = &swapchain,
            .pImageIndices = &image_index,
        };
        VkResult result = vkQueuePresentKHR(device_.queue(), &present);
        if (result != VK_ERROR_OUT_OF_DATE_KHR) check(result, "vkQueuePresentKHR");
        harness_.note_presented(extent_, retirement_.kept());
        const bool resized = harness_.take_resized();
        if (suboptimal || result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR ||
            resized)
            recreate_swapchain();  // this frame was still drawn
    }
    return true;
}

void ChapterRun::record(FrameSlot& slot, uint32_t image_index, const Frame& frame) {
    VkCommandBuffer cmd = slot.cmd;
    VkCommandBufferBeginInfo begin{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
    harness_.gpu_timer().begin(cmd, frame.slot);
    const bool straight = drawn_into();
    const bool screenshot = !options_.screenshot.empty();
    // --screenshot reads back what each frame presents: the swapchain image
    // where the surface lets us read it, else our target.
    const bool read_swapchain = screenshot && swapchain_ && swapchain_->readable();

    // The image the chapter draws into, whose old contents do not matter
    // (UNDEFINED), into the layout the chapter asked for. Our own target: the
    // previous frame's copy must have read it before we overwrite it. A
    // swapchain image: the acquire semaphore, which the submit waits for at
    // the same stage, says when.
    if (frame.target_layout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL) {
        image_barrier(
            cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED, frame.target_layout, frame.target_ready,
            VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT);
    } else if (frame.target_layout != VK_IMAGE_LAYOUT_UNDEFINED) {
        throw Error(
            "ChapterSpec::target_layout is COLOR_ATTACHMENT_OPTIMAL, or UNDEFINED for a chapter "
            "that makes its first barrier itself");
    }

    renderer_->record(frame);  // the chapter draws
    TargetWrite last = renderer_->target_after(frame);
    auto leave = [&](VkImageLayout to, VkPipelineStageFlags2 stage, VkAccessFlags2 access) {
        const VkImageMemoryBarrier2 barrier = barrier_after(last, frame.target, to, stage, access);
        const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                          .imageMemoryBarrierCount = 1,
                                          .pImageMemoryBarriers = &barrier};
        vkCmdPipelineBarrier2(cmd, &dependency);
    };

    // GPU time ends here: what follows is presentation, not the chapter's cost.
    harness_.gpu_timer().end(cmd, frame.slot);

    // [overlay-after-frame]
    if (overlay_) {
        // Over the finished frame, in the layout for drawing: its last write
        // done and visible before the overlay's rendering loads its pixels.
        leave(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
              VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        overlay_->record(cmd, frame.slot, frame.target_view, frame.extent);
        last = drawn_by_colour_output;
    }
    // [/overlay-after-frame]

    // Our target: the chapter's writes must be finished and visible before we
    // copy or read it (and before the next frame's barrier, which waits for
    // the COPY stage, overwrites it).
    if (!straight)
        leave(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
              VK_ACCESS_2_TRANSFER_READ_BIT);

    if (swapchain_) {
        VkImage image = swapchain_->images()[image_index];
        VkImageLayout layout = last.layout;  // drawn straight in: where the chapter left it
        VkPipelineStageFlags2 stage = last.stage;
        VkAccessFlags2 access = last.access;
        if (!straight) {
            // Copy our target in: after the acquire semaphore (waited for at the
            // COPY stage), make the image a copy destination, then copy.
            image_barrier(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
            VkImageCopy region{
                .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                .extent = {frame.extent.width, frame.extent.height, 1},
            };
            vkCmdCopyImage(cmd, frame.target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
            stage = VK_PIPELINE_STAGE_2_COPY_BIT;
            access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        }
        if (read_swapchain) {
            image_barrier(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, stage, access,
                          VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
            record_readback(device_.physical(), device_, cmd, image, swapchain_->format(),
                            frame.extent, slot.readback);
            layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
            stage = VK_PIPELINE_STAGE_2_COPY_BIT;
            access = VK_ACCESS_2_NONE;  // after a read, ordering is all we need
        }
        // Then hand the image to the presentation engine, which waits for the
        // ready_to_present semaphore: no later stage of ours needs to wait.
        image_barrier(cmd, image, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, stage, access,
                      VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    }
    if (screenshot && !read_swapchain)
        record_readback(device_.physical(), device_, cmd, frame.target, format_, frame.extent,
                        slot.readback);

    VKT_CHECK(vkEndCommandBuffer(cmd));
}

VkPipelineStageFlags2 ChapterRun::acquire_wait_stage() const {
    return drawn_into() ? VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT
                        : VK_PIPELINE_STAGE_2_COPY_BIT;
}

VkPipelineStageFlags2 ChapterRun::target_ready() const {
    return drawn_into() ? VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT
                        : VK_PIPELINE_STAGE_2_NONE;
}

}  // namespace detail

VkImageMemoryBarrier2 barrier_after(const TargetWrite& written, VkImage image, VkImageLayout to,
                                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    if (written.layout == VK_IMAGE_LAYOUT_UNDEFINED ||
        written.layout == VK_IMAGE_LAYOUT_PREINITIALIZED ||
        written.stage == VK_PIPELINE_STAGE_2_NONE)
        throw Error(
            "Renderer::target_after: a target the chapter wrote has a layout that keeps its "
            "pixels and the stage that wrote them, not UNDEFINED, PREINITIALIZED or NONE");
    return {
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
        .srcStageMask = written.stage,
        .srcAccessMask = written.access,
        .dstStageMask = dst_stage,
        .dstAccessMask = dst_access,
        .oldLayout = written.layout,
        .newLayout = to,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1},
    };
}

int run_chapter(int argc, char** argv, const ChapterSpec& spec, const RendererFactory& factory) {
    return run_in_harness(argc, argv, spec, detail::frames_in_flight, [&](Harness& harness) {
        detail::ChapterRun run(harness);
        run.run(factory);
    });
}

int run_text_chapter(int argc, char** argv, Flags flags,
                     const std::function<int(const Options&)>& body) {
    return detail::guarded(argc, argv, flags, {}, {}, body);
}

}  // namespace vkt
