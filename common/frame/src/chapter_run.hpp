#pragma once
// The runner's own class (chapter 03), private to common/frame: not on any
// include path, so no chapter sees it. Its members live in two files, one
// concept each:
//
//   presentation.cpp  where the picture goes: a window's swapchain, a headless
//                     surface's swapchain, or only an offscreen image of our
//                     own; choosing one, creating it, and recreating it when
//                     the window changes
//   runner.cpp        the frame loop: frame slots, waiting, acquiring,
//                     recording, submitting, presenting, screenshots and
//                     --benchmark, and the exit status

#include "vkt/core/instance.hpp"
#include "vkt/core/swapchain.hpp"
#include "vkt/frame/gpu_timer.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/frame/window.hpp"
#include "vkt/resources/image_io.hpp"
#include "vkt/resources/readback.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vkt::detail {

inline constexpr uint32_t frames_in_flight = 2;

enum class Presentation { window, headless_surface, offscreen };

// "window", "headless surface" or "offscreen", as the start-up line and
// --benchmark's JSON say it.
const char* presentation_name(Presentation p);

// [frame-slot]
// Per frame in flight: what the CPU records into while the GPU works on the other.
struct FrameSlot {
    CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    Fence done;                // signalled when the GPU finished this slot's last frame
    Semaphore image_acquired;  // signalled when the acquired swapchain image may be written
    Readback readback;         // with --screenshot: what this slot's frame presented
};
// [/frame-slot]

class ChapterRun {
public:
    ChapterRun(const Options& options, const ChapterSpec& spec);
    ~ChapterRun() {
        if (device_) vkDeviceWaitIdle(*device_);  // nothing may be destroyed while in use
    }
    void run(const RendererFactory& factory);
    bool validation() const { return instance_->validation(); }
    std::shared_ptr<const ValidationCounts> counts() const { return instance_->counts(); }

private:
    // presentation.cpp: the window or surface, the instance and device that
    // suit it, the swapchain and our colour target.
    void open_presentation(const Options& options, const ChapterSpec& spec);
    void create_target(VkExtent2D extent);
    void recreate_swapchain();
    void note_presented(VkExtent2D extent);
    // Whether frames are drawn straight into the swapchain's images (chapter
    // 03: an _SRGB swapchain) rather than into target_ and copied in.
    bool direct() const { return swapchain_ && swapchain_->drawable(); }

    // runner.cpp: the frame loop.
    bool draw_frame(uint64_t index, double time, const Input& input);
    void record(FrameSlot& slot, uint32_t image_index, const Frame& frame);
    void save_screenshot(const std::string& path);

    const Options& options_;
    const ChapterSpec& spec_;
    Presentation presentation_ = Presentation::offscreen;
    std::unique_ptr<Window> window_;
    std::unique_ptr<Instance> instance_;
    SurfaceHandle surface_;
    std::unique_ptr<Device> device_;
    std::unique_ptr<Swapchain> swapchain_;
    Image target_;
    ImageView target_storage_;  // with ChapterSpec::storage_target: see create_target
    VkFormat storage_format_ = VK_FORMAT_UNDEFINED;  // Context::storage_format
    std::vector<FrameSlot> slots_;
    GpuTimer gpu_timer_;
    std::unique_ptr<Renderer> renderer_;
    std::vector<double> cpu_ms_;
    std::optional<uint32_t> last_slot_;  // the slot of the last frame submitted
    VkExtent2D presented_{};             // the size of the last frame presented
};

}  // namespace vkt::detail
