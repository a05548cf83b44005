#pragma once
// The harness around a frame loop, taught in chapter 03, whose main.cpp writes
// its swapchain and frame loop itself inside it. The harness is everything
// else a drawing chapter's command line asks for: a window, a headless surface
// or no surface at all (--headless, --offscreen); the instance (--validation)
// and the device that can present there (--device, --size); how many frames
// and what time each shows (--frames); --screenshot; --benchmark; the start-up
// line, the events the window tests wait for, and the exit status. The runner
// (runner.hpp) is chapter 03's loop as a helper, for chapters 04 on, inside
// the same harness.

#include "vkt/core/device.hpp"
#include "vkt/core/instance.hpp"
#include "vkt/frame/args.hpp"
#include "vkt/frame/gpu_timer.hpp"
#include "vkt/frame/input.hpp"
#include "vkt/frame/window.hpp"
#include "vkt/resources/readback.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

struct ChapterSpec {
    std::string name;   // "04_triangle"
    std::string title;  // shown in the window's title bar
    DeviceRequirements requirements;
    std::vector<OptionSpec> options;  // the chapter's own flags (--model, --lights, ...)
    InputUse input = InputUse::none;  // what input the chapter wants in a window (chapter 11)
    // The on-screen overlay of the chapter's settings (Renderer::overlay,
    // chapter 21), in a window run without --frames, or in any run with
    // --overlay on (a flag only such chapters take); its CMake call says
    // OVERLAY too, for the overlay's shaders. The window then reports the
    // pointer (InputUse::pointer).
    bool overlay = false;
    // The chapter may write its frames from a compute shader: give our own
    // target a storage view (Frame::target_storage, chapter 20). Only where
    // asked for, since a storage usage can cost a colour target its
    // compression on some GPUs. (The runner's; chapter 03 has no use for it.)
    bool storage_target = false;
    // The chapter writes its frame with transfer commands (a clear, a copy
    // into Frame::target): a swapchain image it draws straight into then needs
    // TRANSFER_DST usage, which the specification does not promise. Where the
    // surface lacks it, the frame goes into our own target instead.
    bool transfers_into_target = false;
    // The layout record() wants the target in (Frame::target_layout): the
    // runner's barrier takes it there from UNDEFINED. A chapter whose first
    // write differs from frame to frame asks for UNDEFINED and makes that
    // barrier itself, so that no barrier undoes another (chapter 20).
    VkImageLayout target_layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    // Checks between the chapter's own flags (two that contradict each other),
    // run right after parsing, before any Vulkan object exists: throw
    // UsageError, and the chapter exits with status 2 like any bad argument.
    std::function<void(const Options&)> check_options;
};

enum class Presentation { window, headless_surface, offscreen };

// "window", "headless surface" or "offscreen", as the start-up line and
// --benchmark's JSON say it.
const char* presentation_name(Presentation p);

// Where a run's frames go, as the start-up line and --benchmark's JSON say it.
struct Destination {
    VkFormat swapchain_format = VK_FORMAT_UNDEFINED;  // UNDEFINED: no swapchain (offscreen)
    VkPresentModeKHR present_mode = VK_PRESENT_MODE_FIFO_KHR;
    uint32_t images = 0;      // in the swapchain
    bool drawn_into = false;  // frames go straight into its images, else are copied in
    VkExtent2D extent{};      // the image the chapter draws into: its size and format
    VkFormat format = VK_FORMAT_UNDEFINED;
};

class Harness {
public:
    // Opens the window or the headless surface (or neither), then the instance
    // and the device that suit it. frames_in_flight: how many frames the loop
    // keeps in flight (--benchmark's GPU timer has queries for each).
    Harness(const Options& options, const ChapterSpec& spec, uint32_t frames_in_flight);
    ~Harness();
    Harness(const Harness&) = delete;
    Harness& operator=(const Harness&) = delete;

    const Options& options() const { return options_; }
    const ChapterSpec& spec() const { return spec_; }
    Presentation presentation() const { return presentation_; }
    VkInstance instance() const { return *instance_; }
    const Device& device() const { return *device_; }
    VkSurfaceKHR surface() const { return surface_; }  // VK_NULL_HANDLE offscreen
    Window* window() const { return window_.get(); }   // nullptr unless in a window
    bool validation() const { return instance_->validation(); }
    // Whether each present can carry a fence that says when it is over
    // (VK_KHR_/EXT_swapchain_maintenance1, enabled where the instance and device
    // offer it): how a retired swapchain is known to be free
    // (vkt/core/swapchain_retirement.hpp).
    bool present_fences() const { return present_fences_; }
    std::shared_ptr<const ValidationCounts> counts() const { return instance_->counts(); }
    // What the tests pretend no device has (VKT_HIDE_FEATURES=name,name,...),
    // read once at start; the device checks and the chapters ask it.
    const HiddenNames& hidden() const { return hidden_; }

    // The loop. Once before each frame: polls the window, and says whether to
    // draw (`draw`), to stop (--frames reached, or the window closed), or to
    // draw after recreating the swapchain (`restored`: the window was
    // minimised, which the harness waited out, saying so, and the surface may
    // have changed meanwhile). With --benchmark it also takes the CPU time of
    // the frame before, if that frame was drawn (frames_drawn went up).
    enum class Next { stop, draw, restored };
    Next next_frame(uint64_t frames_drawn);
    // The time a frame shows, in seconds: frame index / 60 headless or with
    // --frames (the same frame always gives the same picture), else the clock.
    double time(uint64_t index) const;
    // Whether the time follows the frame index rather than the clock.
    bool fixed_step() const;
    // Whether the runner draws the chapter's overlay (ChapterSpec::overlay):
    // in a window run without --frames, or wherever --overlay on asks.
    bool overlay() const;
    // What --overlay said: "on", "off", or "" (not given).
    std::string_view overlay_choice() const;
    // The size to make a swapchain: the window's framebuffer, or --size.
    VkExtent2D wanted_extent() const;
    // True once after the window changed size (never headless).
    bool take_resized();
    // Sleeps while the window is minimised (a 0x0 window can have no
    // swapchain); false if it should close instead. True at once headless.
    bool wait_while_minimised();

    // --benchmark's GPU time (disabled without --benchmark: every call does nothing).
    GpuTimer& gpu_timer() { return gpu_timer_; }

    // The start-up line: the device, where the frames go, validation.
    void announce(const Destination& where) const;
    // "presented a frame at WxH" for the first frame of each size, and
    // "swapchain recreated at WxH": the events the window tests wait for.
    // retired_kept: the old swapchains still kept after this present; once
    // after each recreation, "retired swapchains down to N kept" when N <= 1
    // (the storm tests wait for it: retirement lets the old ones go).
    void note_presented(VkExtent2D extent, size_t retired_kept = 0);
    // kept: retired swapchains still waiting for their presents to end.
    void note_recreated(VkExtent2D extent, size_t kept);
    // After the loop, the GPU idle: --benchmark's last GPU times and its JSON,
    // and --screenshot's PNG from the last frame's read-back (null if no frame
    // was drawn).
    void finish(const Destination& where, const Readback* last_frame);

private:
    void open_presentation();

    const Options& options_;
    const ChapterSpec& spec_;
    uint32_t frames_in_flight_;
    HiddenNames hidden_;
    Presentation presentation_ = Presentation::offscreen;
    std::unique_ptr<Window> window_;
    std::unique_ptr<Instance> instance_;
    SurfaceHandle surface_;
    std::unique_ptr<Device> device_;
    bool present_fences_ = false;
    GpuTimer gpu_timer_;  // after device_: destroyed before it
    double start_seconds_ = 0;
    uint64_t last_drawn_ = 0;
    std::chrono::steady_clock::time_point frame_begin_;
    std::vector<double> cpu_ms_;
    VkExtent2D presented_{};  // the size of the last frame presented
    bool draining_ = false;   // recreated, old swapchains not yet down to one
};

// Runs a frame loop inside the harness; returns the process exit status: 0
// done, 1 an error (or any validation message), 2 bad command line.
int run_in_harness(int argc, char** argv, const ChapterSpec& spec, uint32_t frames_in_flight,
                   const std::function<void(Harness&)>& loop);

}  // namespace vkt
