#pragma once
// When a retired swapchain may be destroyed, taught in chapter 03.
//
// vkCreateSwapchainKHR with oldSwapchain retires the old one, but its last
// presents may still be on their way to the screen, and each waits on one of
// its ready_to_present semaphores. vkDeviceWaitIdle does not cover that: it
// waits for queue work, not for the presentation engine. So the old swapchain
// (and the semaphores its presents wait on) is kept here until something
// proves its presents are over, and destroyed then:
//
//   present fences  VK_KHR_swapchain_maintenance1 (or EXT): each vkQueuePresentKHR gets
//                   a fence the driver signals once the present no longer
//                   needs its semaphores and image. The specification's answer.
//   fallback        without it, the first image the new swapchain presents is
//                   watched: once that image is acquired again and the frame
//                   that waited for it has finished, the presentation engine
//                   has let go of it, so that present is over, and with it
//                   every present queued before it (one queue presents in
//                   order). The best a program can know without the extension.

#include "vkt/core/owned.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace vkt {

class SwapchainRetirement {
public:
    // present_fences: swapchain_maintenance1's swapchainMaintenance1 is on.
    SwapchainRetirement(VkDevice device, bool present_fences);
    // Waits until every present is proven over (present fences), or for the
    // device (fallback: at the end nothing later can prove it), then destroys
    // what was retired. Destroy this before the current swapchain.
    ~SwapchainRetirement();
    SwapchainRetirement(const SwapchainRetirement&) = delete;
    SwapchainRetirement& operator=(const SwapchainRetirement&) = delete;

    bool present_fences() const { return present_fences_; }

    // For VkPresentInfoKHR::pNext: a VkSwapchainPresentFenceInfoEXT with a
    // fresh fence for this present (valid until the next call), or nullptr.
    const void* present(uint32_t image);
    // vkAcquireNextImageKHR gave `image` to the frame in `slot`.
    void acquired(uint32_t image, uint32_t slot);
    // The CPU has waited for `slot`'s fence: its frame is finished. Then
    // destroys whatever is proven free: call it once a frame.
    void slot_finished(uint32_t slot);
    // vkCreateSwapchainKHR has just retired `old` (a swapchain owner with the
    // semaphores its presents wait on): kept until its presents are over.
    template <class Old>
    void retire(Old old) {
        retired_.push_back({generation_, std::make_shared<Old>(std::move(old))});
        ++generation_;
        first_present_.reset();
    }
    // How many retired swapchains are still kept (for the tests' log line).
    size_t kept() const { return retired_.size(); }

private:
    void collect();
    struct Retired {
        uint64_t generation;  // of the swapchain it was
        std::shared_ptr<void> owner;
    };
    struct PresentFence {
        uint64_t generation;  // of the swapchain presented to
        Fence fence;
    };
    VkDevice device_;
    bool present_fences_;
    uint64_t generation_ = 0;  // of the current swapchain
    std::vector<Retired> retired_;
    // Present fences: those not yet seen signalled, and signalled ones reset for reuse.
    std::vector<PresentFence> pending_;
    std::vector<Fence> spare_;
    VkFence fence_ = VK_NULL_HANDLE;
    VkSwapchainPresentFenceInfoEXT fence_info_{};
    // Fallback: the image of the current swapchain's first present; per slot,
    // the generation whose first present that slot's frame proves over; and
    // the generation before which every present is proven over.
    std::optional<uint32_t> first_present_;
    std::vector<std::optional<uint64_t>> proves_;
    uint64_t proven_ = 0;
};

}  // namespace vkt
