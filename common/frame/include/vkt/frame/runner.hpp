#pragma once
// The chapter runner: chapter 03's swapchain and frame loop as a helper, inside
// chapter 03's harness (harness.hpp: the command line, the window or headless
// surface or offscreen images, the device, screenshots and benchmarks). Every
// chapter from 04 on only says what to record into each frame.
//
// The contract with a chapter: each frame, record() gets a command buffer and
// the frame's colour target in an _SRGB format (the acquired swapchain image
// where its format allows, else an image of our own), with undefined contents,
// in the layout the frame names (Frame::target_layout: the chapter's
// ChapterSpec::target_layout, COLOR_ATTACHMENT_OPTIMAL unless it asks for
// another). record() draws into it and says the layout it leaves it in and
// the stage and access of its last write (Renderer::target_after); the
// runner's next barrier waits for exactly that, and takes it from there: presents
// it, copies our own into the swapchain image, or keeps it offscreen.
// Where the chapter asks for it (ChapterSpec::storage_target), a frame drawn
// into our own target also carries a storage view of it
// (Frame::target_storage), for a compute pass that writes the pixels itself.

#include "vkt/core/device.hpp"
#include "vkt/frame/args.hpp"
#include "vkt/frame/gpu_timer.hpp"
#include "vkt/frame/harness.hpp"
#include "vkt/frame/input.hpp"
#include "vkt/frame/overlay.hpp"
#include "vkt/resources/upload.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vkt {

// What a chapter's renderer may use; it stays valid for the renderer's life.
struct Context {
    const Options& options;
    std::string chapter;  // "04_triangle": where its shaders are
    VkInstance instance;
    VkPhysicalDevice physical;
    VkDevice device;
    VkQueue queue;
    uint32_t queue_family;
    // Chapter 29's second queue (DeviceRequirements::compute_family): of a
    // compute-only family where the device has one, else `queue` itself.
    VkQueue compute_queue;
    uint32_t compute_family;
    VkFormat color_format;  // the colour target's format (always an _SRGB format)
    // The format of Frame::target_storage where a frame has one: the _UNORM
    // format with color_format's byte order. VK_FORMAT_UNDEFINED: never (the
    // chapter did not ask, or the device cannot store to that format).
    VkFormat storage_format;
    VkExtent2D extent;  // the colour target's size at start (see Renderer::resize)
    uint32_t frames_in_flight;
    const VkPhysicalDeviceProperties& properties;  // limits, name, ...
    // What the tests pretend no device has (VKT_HIDE_FEATURES): a chapter that
    // checks a property itself asks it too, so the tests can play a device
    // whose property falls short.
    const HiddenNames& hidden;
    const FeatureChain& features;  // what was enabled: ask it about optional features

    // What the upload helpers need (chapter 05).
    Gpu gpu() const { return {physical, device, queue, queue_family}; }
};

// [renderer-contract]
// The layout a chapter leaves its target in, and the stage and access of the
// last write to it: what the runner's next barrier waits for. The layout alone
// does not say it (a fragment shader's storage write and a compute shader's
// both leave GENERAL), so the chapter names all three.
struct TargetWrite {
    VkImageLayout layout;
    VkPipelineStageFlags2 stage;
    VkAccessFlags2 access;
};
// The three ways the chapters write their targets' last pixels.
inline constexpr TargetWrite drawn_by_colour_output{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};
inline constexpr TargetWrite stored_by_compute{VK_IMAGE_LAYOUT_GENERAL,
                                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr TargetWrite written_by_transfer{VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                                 VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                                                 VK_ACCESS_2_TRANSFER_WRITE_BIT};

struct Frame {
    VkCommandBuffer cmd;
    VkImage target;
    VkImageView target_view;
    // A view of the same image in Context::storage_format, for compute
    // shaders (imageStore writes the sRGB-encoded bytes as they are; the
    // image must be in VK_IMAGE_LAYOUT_GENERAL then). VK_NULL_HANDLE where
    // there is none: the frame goes straight into a swapchain image, or
    // Context::storage_format is VK_FORMAT_UNDEFINED.
    VkImageView target_storage;
    VkExtent2D extent;
    // The layout `target` is in as record() begins. UNDEFINED (a chapter
    // whose ChapterSpec::target_layout asks for it): untouched, and the
    // chapter's first barrier on it must start at `target_ready`, the stage
    // after which it may be written (where the acquire semaphore is waited
    // for, or the last frame's copy of our own image is done).
    VkImageLayout target_layout;
    VkPipelineStageFlags2 target_ready;
    uint64_t index;  // 0, 1, 2, ...
    double time;    // seconds: index / 60 headless or with --frames (reproducible), else wall clock
    uint32_t slot;  // which frame in flight, 0 .. frames_in_flight - 1
    const Input& input;  // what the user did since the last frame (chapter 11); may be empty
    GpuTimer* timer;     // null unless --benchmark: use gpu_scope()

    // Times the commands recorded while the returned object lives as a named
    // GPU scope, which --benchmark reports (chapter 13):
    //   { auto scope = frame.gpu_scope("simulate"); vkCmdDispatch(...); }
    GpuScope gpu_scope(std::string_view name) const { return {timer, cmd, slot, name}; }
};

// Chapter 29's: semaphores the frame's submit waits for and signals, beside
// the runner's own (the acquire and the present semaphores).
struct FrameSemaphores {
    std::vector<VkSemaphoreSubmitInfo> wait;
    std::vector<VkSemaphoreSubmitInfo> signal;
};

class Renderer {
public:
    virtual ~Renderer() = default;
    virtual void record(const Frame& frame) = 0;
    // How record() left frame.target: its layout and its last write's stage
    // and access (TargetWrite, below). Drawn by the colour output unless the
    // chapter says otherwise. Asked after each record().
    virtual TargetWrite target_after(const Frame&) const { return drawn_by_colour_output; }
    // What the frame's submit must wait for and signal besides the runner's
    // own: work the chapter submitted itself, to this queue or another
    // (chapter 29). Asked after each record().
    virtual FrameSemaphores semaphores(const Frame&) { return {}; }
    // The colour target changed size (the window was resized); the GPU is idle.
    virtual void resize(VkExtent2D) {}
    // Chapter 21's overlay, in a window: the chapter's settings as widgets,
    // each bound to a value it owns (vkt/frame/overlay.hpp). Called before
    // record() each frame, so a change shows in that frame.
    virtual void overlay(OverlayPanel&) {}
    // Once, after the last frame, the GPU idle: where a check that submits
    // GPU work of its own (--verify) runs, never inside record().
    virtual void verify() {}
};
// [/renderer-contract]

// The runner's barrier after record(): from how the chapter left `image`
// (written) to layout `to` for dst_stage's dst_access. Throws Error, naming
// it, for a TargetWrite no barrier can start from (UNDEFINED, no stage).
VkImageMemoryBarrier2 barrier_after(const TargetWrite& written, VkImage image, VkImageLayout to,
                                    VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access);

using RendererFactory = std::function<std::unique_ptr<Renderer>(const Context&)>;

// Runs a drawing chapter; returns the process exit status:
// 0 done, 1 an error (or any validation message), 2 bad command line.
int run_chapter(int argc, char** argv, const ChapterSpec& spec, const RendererFactory& factory);

// For the text chapters 01 and 02: parses the command line (accepting the
// flags `flags` names), runs body, and turns exceptions into one clear line and
// exit status 1 (2 for usage).
int run_text_chapter(int argc, char** argv, Flags flags,
                     const std::function<int(const Options&)>& body);

}  // namespace vkt
