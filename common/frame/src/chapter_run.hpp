#pragma once
// The runner's own class (chapter 03's loop), private to common/frame: not on
// any include path, so no chapter sees it. Where the picture goes (window,
// headless surface, offscreen), the instance and the device are the harness's
// (harness.cpp); the runner's members live in two files, one concept each:
//
//   presentation.cpp  the swapchain and our own colour target: creating them,
//                     and recreating them when the window changes
//   runner.cpp        the frame loop: frame slots, waiting, acquiring,
//                     recording, submitting, presenting, the screenshot's
//                     read-back

#include "vkt/core/swapchain.hpp"
#include "vkt/core/swapchain_retirement.hpp"
#include "vkt/frame/harness.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/readback.hpp"

#include "overlay.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace vkt::detail {

inline constexpr uint32_t frames_in_flight = 2;

// Per frame in flight: what the CPU records into while the GPU works on the other.
struct FrameSlot {
    CommandPool pool;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    Fence done;                // signalled when the GPU finished this slot's last frame
    Semaphore image_acquired;  // signalled when the acquired swapchain image may be written
    Readback readback;         // with --screenshot: what this slot's frame presented
};

// Chapter 03's frame loop as a helper, inside chapter 03's harness (which
// holds the window or surface, the instance and the device).
class ChapterRun {
public:
    explicit ChapterRun(Harness& harness);
    ~ChapterRun() {
        vkDeviceWaitIdle(device_);  // nothing may be destroyed while in use
    }
    ChapterRun(const ChapterRun&) = delete;
    ChapterRun& operator=(const ChapterRun&) = delete;
    void run(const RendererFactory& factory);

private:
    // presentation.cpp: the swapchain and our colour target.
    void create_swapchain();
    void create_target(VkExtent2D extent);
    void recreate_swapchain();
    // Whether frames are drawn straight into the swapchain's images (chapter
    // 03: an _SRGB swapchain) rather than into own_ and copied in.
    bool drawn_into() const { return swapchain_ && swapchain_->drawn_into(); }
    // Where the submit waits for the acquire semaphore: at the first write to
    // the swapchain image, the chapter's drawing or our copy.
    VkPipelineStageFlags2 acquire_wait_stage() const;
    // The stage after which this frame's target may be written (Frame::
    // target_ready). The swapchain image: after the acquire wait. Our own
    // image: at once (NONE), since each frame slot has its own, and the
    // slot's fence, waited for before recording, says its last frame is over.
    VkPipelineStageFlags2 target_ready() const;
    // What the start-up line and --benchmark say about where frames go.
    Destination destination() const;

    // runner.cpp: the frame loop.
    bool draw_frame(uint64_t index, double time, const Input& input);
    void record(FrameSlot& slot, uint32_t image_index, const Frame& frame);

    Harness& harness_;
    const Options& options_;
    const ChapterSpec& spec_;
    const Device& device_;
    std::unique_ptr<Swapchain> swapchain_;
    // Old swapchains until their presents are over; after swapchain_, so it is
    // destroyed first, once the current swapchain's presents are over too.
    SwapchainRetirement retirement_;
    // The colour target's format and size, whichever image it is; our own
    // image only where frames are not drawn straight into the swapchain's.
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    // Our own images, one per frame slot: a single one would make each frame's
    // drawing wait for the last frame's copy out of it, which waits for its
    // acquire, so no two frames would overlap. Empty when drawn straight in.
    std::vector<Image> own_;
    std::vector<ImageView> own_storage_;  // with ChapterSpec::storage_target: see create_target
    VkFormat storage_format_ = VK_FORMAT_UNDEFINED;  // Context::storage_format
    std::vector<FrameSlot> slots_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Overlay> overlay_;   // in a window, for a chapter with ChapterSpec::overlay
    std::optional<uint32_t> last_slot_;  // the slot of the last frame submitted
};

}  // namespace vkt::detail
