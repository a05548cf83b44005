#pragma once
// GPU time from timestamp queries: what the runner's --benchmark reports
// (chapter 03), for the whole frame and for named scopes a chapter marks
// ("simulate", "draw", ...; chapter 13). The queue writes a timestamp when the
// work before it has reached the named stage; the difference of two, times
// limits.timestampPeriod, is nanoseconds. Each frame in flight has its own
// queries, read back once that frame's fence has been waited for.

#include "vkt/core/owned.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace vkt {

class GpuTimer {
public:
    static constexpr uint32_t max_scopes = 8;

    GpuTimer() = default;  // disabled: every call does nothing
    // Disabled as well where the queue family cannot write timestamps.
    GpuTimer(VkPhysicalDevice physical, VkDevice device, uint32_t queue_family, uint32_t slots);

    explicit operator bool() const { return bool(pool_); }
    // The whole frame: recorded at the start and the end of the chapter's work.
    void begin(VkCommandBuffer cmd, uint32_t slot);
    void end(VkCommandBuffer cmd, uint32_t slot);
    // A named scope inside the frame; the first use of a name registers it
    // (at most max_scopes names). A scope may be timed once per frame.
    void begin_scope(VkCommandBuffer cmd, uint32_t slot, std::string_view name);
    void end_scope(VkCommandBuffer cmd, uint32_t slot, std::string_view name);
    // After the slot's frame has finished (its fence waited for): adds the
    // slot's pending times to the samples. Safe to call at any time.
    void collect(uint32_t slot);

    const std::vector<double>& samples_ms() const { return frame_.samples; }
    struct Scope {
        std::string name;
        std::vector<double> samples;  // ms
    };
    const std::vector<Scope>& scopes() const { return scopes_; }

private:
    struct Track {
        std::vector<double> samples;
    };
    uint32_t scope_index(std::string_view name);
    uint32_t first_query(uint32_t slot, uint32_t track) const;  // track 0: the frame
    void read(uint32_t slot, uint32_t track, std::vector<double>& out);

    VkDevice device_ = VK_NULL_HANDLE;
    QueryPool pool_;
    uint64_t mask_ = 0;  // timestampValidBits: higher bits are garbage
    double period_ns_ = 0;
    Track frame_;
    std::vector<Scope> scopes_;
    // pending_[slot][track]: written in the slot's last frame, not yet read.
    std::vector<std::vector<bool>> pending_;
    std::vector<std::vector<bool>> open_;  // begun, not yet ended
};

// Times the commands recorded during its lifetime as one named GPU scope.
class GpuScope {
public:
    GpuScope(GpuTimer* timer, VkCommandBuffer cmd, uint32_t slot, std::string_view name)
        : timer_(timer), cmd_(cmd), slot_(slot), name_(name) {
        if (timer_) timer_->begin_scope(cmd_, slot_, name_);
    }
    // end_scope finds the scope begin_scope made; it could throw only for
    // want of memory, which may well end the program.
    ~GpuScope() {  // NOLINT(bugprone-exception-escape)
        if (timer_) timer_->end_scope(cmd_, slot_, name_);
    }
    GpuScope(const GpuScope&) = delete;
    GpuScope& operator=(const GpuScope&) = delete;

private:
    GpuTimer* timer_;
    VkCommandBuffer cmd_;
    uint32_t slot_;
    std::string name_;
};

}  // namespace vkt
