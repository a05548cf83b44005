// Chapter 03's swapchain retirement: see swapchain_retirement.hpp for why.

#include "vkt/core/swapchain_retirement.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>

namespace vkt {

SwapchainRetirement::SwapchainRetirement(VkDevice device, bool present_fences)
    : device_(device), present_fences_(present_fences) {}

SwapchainRetirement::~SwapchainRetirement() {
    // A present whose vkQueuePresentKHR failed outright (a lost surface) may
    // never signal its fence: on that error path, wait a bounded while, then
    // settle for the device being idle.
    constexpr uint64_t one_second = 1'000'000'000;
    for (const PresentFence& p : pending_) {
        VkFence fence = p.fence;
        if (vkWaitForFences(device_, 1, &fence, VK_TRUE, one_second) != VK_SUCCESS) break;
    }
    vkDeviceWaitIdle(device_);
    retired_.clear();  // the old swapchains and their semaphores go now
}

const void* SwapchainRetirement::present(uint32_t image) {
    if (!present_fences_) {
        if (!first_present_) first_present_ = image;
        return nullptr;
    }
    Fence fence;
    if (spare_.empty()) {
        fence = create_fence(device_, false);
    } else {
        fence = std::move(spare_.back());
        spare_.pop_back();
    }
    fence_ = fence;
    pending_.push_back({generation_, std::move(fence)});
    fence_info_ = VkSwapchainPresentFenceInfoEXT{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_PRESENT_FENCE_INFO_EXT,
        .swapchainCount = 1,  // one fence for each swapchain presented to
        .pFences = &fence_,
    };
    return &fence_info_;
}

void SwapchainRetirement::acquired(uint32_t image, uint32_t slot) {
    if (present_fences_) return;
    if (proves_.size() <= slot) proves_.resize(slot + 1);
    // The image of this swapchain's first present, acquired again after it:
    // when this slot's frame is finished, that present is over.
    if (first_present_ == image) proves_[slot] = generation_;
}

void SwapchainRetirement::slot_finished(uint32_t slot) {
    if (slot < proves_.size() && proves_[slot]) {
        proven_ = std::max(proven_, *proves_[slot]);  // every older generation's presents are over
        proves_[slot].reset();
    }
    collect();
}

void SwapchainRetirement::collect() {
    uint64_t free_below = proven_;  // fallback: generations below this are free
    if (present_fences_) {
        // Signalled fences go back to the spare list; the oldest generation
        // with a present still pending is the first that is not free.
        free_below = generation_ + 1;
        for (auto p = pending_.begin(); p != pending_.end();) {
            if (vkGetFenceStatus(device_, p->fence) == VK_SUCCESS) {
                VkFence fence = p->fence;
                VKT_CHECK(vkResetFences(device_, 1, &fence));
                spare_.push_back(std::move(p->fence));
                p = pending_.erase(p);
            } else {
                free_below = std::min(free_below, p->generation);
                ++p;
            }
        }
    }
    std::erase_if(retired_, [&](const Retired& r) { return r.generation < free_below; });
}

}  // namespace vkt
