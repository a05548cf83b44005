// The frame loop (chapter 03). Where each frame ends up, a window, a headless
// surface or an offscreen image, is presentation.cpp's.

#include "vkt/frame/runner.hpp"

#include "chapter_run.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/frame/stats.hpp"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace vkt {
namespace detail {
namespace {

constexpr double fixed_time_step = 1.0 / 60.0;
constexpr uint32_t default_headless_frames = 60;

// Fails early, with the reason, if the screenshot could not be written: better
// than finding out after a long run. Leaves no file behind.
void check_writable(const std::string& path) {
    const bool existed = std::filesystem::exists(path);
    std::FILE* file = std::fopen(path.c_str(), "ab");
    if (!file) throw Error("cannot write " + path + ": " + std::strerror(errno));
    std::fclose(file);
    if (!existed) std::filesystem::remove(path);
}

}  // namespace

ChapterRun::ChapterRun(const Options& options, const ChapterSpec& spec)
    : options_(options), spec_(spec) {
    if (!options.screenshot.empty()) check_writable(options.screenshot);
    open_presentation(options, spec);  // window or surface, instance, device, swapchain, target

    for (uint32_t i = 0; i < frames_in_flight; ++i) {
        FrameSlot slot{
            .pool = create_command_pool(*device_, device_->queue_family(),
                                        VK_COMMAND_POOL_CREATE_TRANSIENT_BIT),
            .done = create_fence(*device_, true),  // signalled: the first wait returns at once
            .image_acquired = create_semaphore(*device_),
        };
        VkCommandBufferAllocateInfo allocate{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
            .commandPool = slot.pool,
            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
            .commandBufferCount = 1,
        };
        VKT_CHECK(vkAllocateCommandBuffers(*device_, &allocate, &slot.cmd));
        slots_.push_back(std::move(slot));
    }

    if (options.benchmark) {
        // GPU time from two timestamps per frame, where the queue can write them.
        gpu_timer_ =
            GpuTimer(device_->physical(), *device_, device_->queue_family(), frames_in_flight);
    }

    std::string where = presentation_name(presentation_);
    if (swapchain_)
        where += std::string(" ") + format_name(swapchain_->format()) + " " +
                 present_mode_name(swapchain_->present_mode()) + " x" +
                 std::to_string(swapchain_->images().size()) +
                 (swapchain_->drawable() ? " drawn into" : " copied into");
    std::fprintf(stderr, "%s: %s, %s, %ux%u %s, validation %s\n", spec.name.c_str(),
                 device_->properties().deviceName, where.c_str(), target_.extent.width,
                 target_.extent.height, format_name(target_.format),
                 instance_->validation() ? "on (with synchronisation)" : "off");
}

void ChapterRun::run(const RendererFactory& factory) {
    renderer_ = factory(Context{
        .options = options_,
        .chapter = spec_.name,
        .instance = *instance_,
        .physical = device_->physical(),
        .device = *device_,
        .queue = device_->queue(),
        .queue_family = device_->queue_family(),
        .color_format = target_.format,
        .storage_format = storage_format_,
        .extent = target_.extent,
        .frames_in_flight = frames_in_flight,
        .properties = device_->properties(),
        .features = device_->features(),
    });

    const uint64_t frame_count =
        options_.frames.value_or(window_ ? UINT64_MAX : default_headless_frames);
    // Headless, or with --frames in a window, time is a function of the frame
    // index only, so the same frame always gives the same picture. An open-ended
    // window run follows the wall clock instead.
    const bool fixed_step = !window_ || options_.frames.has_value();
    const double start = window_ ? window_->seconds() : 0;
    for (uint64_t index = 0; index < frame_count;) {
        if (window_) {
            window_->poll();
            if (window_->should_close()) break;
            // [minimised]
            // A minimised window shows nothing, so draw nothing: sleep until the
            // window manager gives it back (or closes it), then start afresh.
            if (window_->minimised()) {
                std::fprintf(stderr, "%s: minimised after %llu frames: waiting\n",
                             spec_.name.c_str(), (unsigned long long)index);
                window_->wait_while_minimised();
                if (window_->should_close()) break;
                std::fprintf(stderr, "%s: restored, still at %llu frames\n", spec_.name.c_str(),
                             (unsigned long long)index);
                recreate_swapchain();
                continue;
            }
            // [/minimised]
        }
        const double time =
            fixed_step ? double(index) * fixed_time_step : window_->seconds() - start;
        const auto begin = std::chrono::steady_clock::now();
        // Input only in an open-ended window run: with --frames, as headless,
        // every frame sees an empty snapshot, so the run is reproducible.
        const Input input = window_ && fixed_step == false ? window_->take_input() : Input{};
        if (!draw_frame(index, time, input)) {
            // The swapchain was recreated instead: try again, with this input
            // given back, since no frame saw it (a key tapped now still counts).
            if (window_) window_->give_back_input(input);
            continue;
        }
        if (options_.benchmark)  // only --benchmark keeps a time per frame (8 bytes)
            cpu_ms_.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
                    .count());
        ++index;
    }

    VKT_CHECK(vkDeviceWaitIdle(*device_));
    for (uint32_t i = 0; i < frames_in_flight; ++i) gpu_timer_.collect(i);
    if (!options_.screenshot.empty()) {
        if (!last_slot_) throw Error("no frame was drawn, so there is no screenshot to write");
        save_screenshot(options_.screenshot);
    }

    if (options_.benchmark) {
        std::string scopes;  // "name": {summary}, one per GPU scope the chapter named
        for (const auto& scope : gpu_timer_.scopes())
            scopes += (scopes.empty() ? "" : ", ") + json_string(scope.name) + ": " +
                      json_summary(scope.samples);
        std::printf(
            "{\"chapter\": %s, \"device\": %s, \"presentation\": %s, \"width\": %u, \"height\": "
            "%u, \"into_swapchain\": %s, "
            "\"frames\": %zu, \"cpu_frame_ms\": %s, \"gpu_frame_ms\": %s, \"gpu_scopes_ms\": "
            "{%s}}\n",
            json_string(spec_.name).c_str(), json_string(device_->properties().deviceName).c_str(),
            json_string(presentation_name(presentation_)).c_str(), target_.extent.width,
            target_.extent.height,
            !swapchain_              ? "null"
            : swapchain_->drawable() ? "\"drawn\""
                                     : "\"copied\"",
            cpu_ms_.size(), json_summary(cpu_ms_).c_str(),
            json_summary(gpu_timer_.samples_ms()).c_str(), scopes.c_str());
    }
    renderer_.reset();
}

// [wait-acquire]
bool ChapterRun::draw_frame(uint64_t index, double time, const Input& input) {
    const uint32_t slot_index = uint32_t(index % frames_in_flight);
    FrameSlot& slot = slots_[slot_index];

    // Wait until the GPU is done with this slot's previous frame (two frames ago),
    // so its command buffer and semaphore can be used again.
    VkFence done = slot.done;
    VKT_CHECK(vkWaitForFences(*device_, 1, &done, VK_TRUE, UINT64_MAX));
    gpu_timer_.collect(slot_index);

    uint32_t image_index = 0;
    bool suboptimal = false;  // an image was acquired, but recreate after this frame
    if (swapchain_) {
        VkResult result = vkAcquireNextImageKHR(*device_, swapchain_->get(), UINT64_MAX,
                                                slot.image_acquired, VK_NULL_HANDLE, &image_index);
        if (result == VK_ERROR_OUT_OF_DATE_KHR) {  // the window changed: nothing was acquired
            recreate_swapchain();
            return false;
        }
        check(result, "vkAcquireNextImageKHR");
        suboptimal = result == VK_SUBOPTIMAL_KHR;
    }
    VKT_CHECK(vkResetFences(*device_, 1, &done));  // only now that we will submit
    // [/wait-acquire]

    // The chapter draws into the acquired swapchain image itself where it can,
    // else into our own image, which record() then copies into the swapchain's.
    const bool straight_in = direct();
    VKT_CHECK(vkResetCommandPool(*device_, slot.pool, 0));
    record(slot, image_index,
           Frame{slot.cmd, straight_in ? swapchain_->images()[image_index] : target_.image.get(),
                 straight_in ? swapchain_->view(image_index) : target_.view.get(),
                 straight_in ? VK_NULL_HANDLE : target_storage_.get(), target_.extent, index, time,
                 slot_index, input, gpu_timer_ ? &gpu_timer_ : nullptr});

    // [submit]
    // Submit: wait for the acquired image before the first write to it (the
    // chapter's drawing, or our copy), signal the image's own ready_to_present
    // semaphore, and the slot's fence for the CPU.
    VkSemaphoreSubmitInfo wait{
        .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
        .semaphore = slot.image_acquired,
        .stageMask = straight_in ? VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT
                                 : VK_PIPELINE_STAGE_2_COPY_BIT,
    };
    VkSemaphoreSubmitInfo signal{
        .sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
        .semaphore = swapchain_ ? swapchain_->ready_to_present(image_index) : VK_NULL_HANDLE,
        .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
    };
    VkCommandBufferSubmitInfo command{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
        .commandBuffer = slot.cmd,
    };
    VkSubmitInfo2 submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
        .waitSemaphoreInfoCount = swapchain_ ? 1u : 0u,
        .pWaitSemaphoreInfos = &wait,
        .commandBufferInfoCount = 1,
        .pCommandBufferInfos = &command,
        .signalSemaphoreInfoCount = swapchain_ ? 1u : 0u,
        .pSignalSemaphoreInfos = &signal,
    };
    VKT_CHECK(vkQueueSubmit2(device_->queue(), 1, &submit, slot.done));
    // [/submit]
    last_slot_ = slot_index;
    if (!swapchain_) note_presented(target_.extent);

    // [present]
    if (swapchain_) {
        VkSwapchainKHR swapchain = swapchain_->get();
        VkSemaphore ready = swapchain_->ready_to_present(image_index);
        VkPresentInfoKHR present{
            .sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
            .waitSemaphoreCount = 1,
            .pWaitSemaphores = &ready,
            .swapchainCount = 1,
            .pSwapchains = &swapchain,
            .pImageIndices = &image_index,
        };
        VkResult result = vkQueuePresentKHR(device_->queue(), &present);
        if (result != VK_ERROR_OUT_OF_DATE_KHR) check(result, "vkQueuePresentKHR");
        note_presented(target_.extent);
        const bool resized = window_ && window_->take_resized();
        if (suboptimal || result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR ||
            resized)
            recreate_swapchain();  // this frame was still drawn
    }
    // [/present]
    return true;
}

void ChapterRun::record(FrameSlot& slot, uint32_t image_index, const Frame& frame) {
    VkCommandBuffer cmd = slot.cmd;
    VkCommandBufferBeginInfo begin{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
    gpu_timer_.begin(cmd, frame.slot);
    const bool straight_in = direct();
    const bool screenshot = !options_.screenshot.empty();
    // --screenshot reads back what each frame presents: the swapchain image
    // where the surface lets us read it, else our target.
    const bool read_swapchain = screenshot && swapchain_ && swapchain_->readable();

    // [frame-barriers]
    // The image the chapter draws into, whose old contents do not matter
    // (UNDEFINED). Our own target: the previous frame's copy must have read it
    // before we overwrite it. A swapchain image: the acquire semaphore, which
    // the submit waits for at the colour-output stage, says when.
    image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED,
                  VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                  straight_in ? VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT
                              : VK_PIPELINE_STAGE_2_COPY_BIT,
                  VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT);

    renderer_->record(frame);  // the chapter draws

    // GPU time ends here: what follows is presentation, not the chapter's cost.
    gpu_timer_.end(cmd, frame.slot);

    // Our target: the chapter's writes must be finished and visible before we
    // copy or read it (and before the next frame's barrier, which waits for
    // the COPY stage, overwrites it).
    if (!straight_in)
        image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT);

    if (swapchain_) {
        VkImage image = swapchain_->images()[image_index];
        VkImageLayout layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        VkAccessFlags2 access = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        if (!straight_in) {
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
            record_readback(device_->physical(), *device_, cmd, image, swapchain_->format(),
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
    // [/frame-barriers]
    if (screenshot && !read_swapchain)
        record_readback(device_->physical(), *device_, cmd, frame.target, target_.format,
                        frame.extent, slot.readback);

    VKT_CHECK(vkEndCommandBuffer(cmd));
}

void ChapterRun::save_screenshot(const std::string& path) {
    // The last frame's slot holds what that frame presented (see record); the
    // GPU is idle, and the barrier to the HOST stage made the bytes visible.
    const Readback& readback = slots_[*last_slot_].readback;
    write_png(path, to_rgba(readback.buffer.mapped, readback.extent, readback.format));
    std::fprintf(stderr, "%s: wrote %s (%ux%u)\n", spec_.name.c_str(), path.c_str(),
                 readback.extent.width, readback.extent.height);
}

}  // namespace detail

namespace {

std::string program_name(char** argv) {
    return std::filesystem::path(argv[0] ? argv[0] : "chapter").filename().string();
}

// Turns the body's outcome into an exit status: usage errors 2, failures 1.
int guarded(int argc, char** argv, Flags flags, std::span<const OptionSpec> chapter_options,
            const std::function<void(const Options&)>& check_options,
            const std::function<int(const Options&)>& body) {
    const std::string program = program_name(argv);
    const auto usage = [&](const UsageError& e) {
        std::fprintf(stderr, "%s: %s\n%s\n", program.c_str(), e.what(),
                     usage_line(program, flags, chapter_options).c_str());
        return 2;
    };
    Options options;
    try {
        options = parse_args(std::span<const char* const>(argv + 1, size_t(std::max(argc - 1, 0))),
                             flags, chapter_options);
        if (options.help) {
            std::fputs(help_text(program, flags, chapter_options).c_str(), stdout);
            return 0;
        }
        // Flags that contradict each other, before any Vulkan object exists.
        if (check_options) check_options(options);
    } catch (const UsageError& e) {
        return usage(e);
    }
    try {
        return body(options);
    } catch (const UsageError& e) {  // a chapter may find a bad flag later, too
        return usage(e);
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 1;
    }
}

int report_validation(const std::string& program, const ValidationCounts* counts) {
    if (!counts) return 0;
    const uint32_t warnings = counts->warnings, errors = counts->errors;
    std::fprintf(stderr, "%s: validation: %u warnings, %u errors\n", program.c_str(), warnings,
                 errors);
    return warnings + errors > 0 ? 1 : 0;
}

}  // namespace

int run_chapter(int argc, char** argv, const ChapterSpec& spec, const RendererFactory& factory) {
    return guarded(argc, argv, Flags::frame_loop, spec.options, spec.check_options,
                   [&](const Options& options) {
                       std::shared_ptr<const ValidationCounts> counts;
                       {
                           detail::ChapterRun run(options, spec);
                           if (run.validation()) counts = run.counts();
                           run.run(factory);
                       }  // everything destroyed: the layer has said all it will say
                       return report_validation(spec.name, counts.get());
                   });
}

int run_text_chapter(int argc, char** argv, Flags flags,
                     const std::function<int(const Options&)>& body) {
    return guarded(argc, argv, flags, {}, {}, body);
}

}  // namespace vkt
