#pragma once
// GPU time from timestamp queries, one pair per frame in flight: what the
// runner's --benchmark reports (chapter 03). The queue writes a timestamp when
// the work before it has reached the named stage; the difference of two, times
// limits.timestampPeriod, is nanoseconds.

#include "vkt/owned.hpp"

#include <vector>

namespace vkt {

class GpuTimer {
public:
    GpuTimer() = default;  // disabled: begin/end/collect do nothing
    // Disabled as well where the queue family cannot write timestamps.
    GpuTimer(VkPhysicalDevice physical, VkDevice device, uint32_t queue_family, uint32_t slots);

    explicit operator bool() const { return bool(pool_); }
    // Recorded at the start and the end of the work to time, in slot's frame.
    void begin(VkCommandBuffer cmd, uint32_t slot);
    void end(VkCommandBuffer cmd, uint32_t slot);
    // After the slot's frame has finished (its fence waited for): adds the
    // slot's time, if one is pending, to samples(). Safe to call at any time.
    void collect(uint32_t slot);
    const std::vector<double>& samples_ms() const { return samples_; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    QueryPool pool_;
    uint64_t mask_ = 0;  // timestampValidBits: higher bits are garbage
    double period_ns_ = 0;
    std::vector<bool> pending_;
    std::vector<double> samples_;
};

}  // namespace vkt
