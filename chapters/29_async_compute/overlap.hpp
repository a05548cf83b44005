#pragma once
// Chapter 29's measurement (--benchmark): how much of the bloom's time on the
// GPU runs while the graphics queue is drawing. Six timestamps per scene (its
// frame slot's): the scene pass, the bloom and the tone map, each begun and
// ended, written on whichever queue runs that pass. At the end, every bloom's
// interval is laid against the union of all graphics intervals: the part
// inside it ran "under" graphics work, hidden; the rest ran alone.
// Timestamps of two queues are compared here, which Vulkan promises only
// where the device keeps one clock for its queues (the page says what that
// asks of a reader's device); the frame times of the two paths check it.
// The same marks give the GPU's pace: the time between one tone map's end
// and the next, on the graphics queue alone (the runner's gpu_frame_ms times
// only its own command buffer, in async the tone map alone).

#include "vkt/core/check.hpp"
#include "vkt/core/owned.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>
#include <vector>

namespace ch29 {

class Overlap {
public:
    enum Mark { scene_begin, scene_end, bloom_begin, bloom_end, tonemap_begin, tonemap_end, marks };

    Overlap() = default;
    // Off (every call does nothing) unless `on`, and where a family cannot
    // write timestamps (timestampValidBits 0).
    Overlap(VkDevice device, uint32_t slots, bool on, float period)
        : device_(device), period_(period) {
        if (!on) return;
        const VkQueryPoolCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
            .queryType = VK_QUERY_TYPE_TIMESTAMP,
            .queryCount = slots * marks,
        };
        VkQueryPool pool;
        VKT_CHECK(vkCreateQueryPool(device, &info, nullptr, &pool));
        pool_ = vkt::QueryPool(device, pool);
        written_.assign(slots, false);
    }
    explicit operator bool() const { return bool(pool_); }

    // At the start of the slot's first command buffer, before any mark.
    void reset(VkCommandBuffer cmd, uint32_t slot) const {
        if (pool_) vkCmdResetQueryPool(cmd, pool_, slot * marks, marks);
    }
    void mark(VkCommandBuffer cmd, uint32_t slot, Mark m) const {
        if (pool_)
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_,
                                 slot * marks + m);
    }
    // The slot's tone map is recorded: all six will be written.
    void complete(uint32_t slot) {
        if (pool_) written_[slot] = true;
    }
    // Once the slot's frame is over (its timeline value reached): keep its times.
    void collect(uint32_t slot) {
        if (!pool_ || !written_[slot]) return;
        uint64_t t[marks];
        VKT_CHECK(vkGetQueryPoolResults(device_, pool_, slot * marks, marks, sizeof t, t,
                                        sizeof(uint64_t), VK_QUERY_RESULT_64_BIT));
        graphics_.emplace_back(t[scene_begin], t[scene_end]);
        graphics_.emplace_back(t[tonemap_begin], t[tonemap_end]);
        bloom_.emplace_back(t[bloom_begin], t[bloom_end]);
        shown_.push_back(t[tonemap_end]);
        written_[slot] = false;
    }

    // "bloom 0.123 ms median, 0.100 ms of it (81%) under graphics work" on stderr.
    void report(const char* queues) {
        if (!pool_ || bloom_.empty()) return;
        // The graphics intervals' union, as sorted disjoint intervals.
        std::sort(graphics_.begin(), graphics_.end());
        std::vector<Interval> busy;
        for (const Interval& g : graphics_)
            if (!busy.empty() && g.first <= busy.back().second)
                busy.back().second = std::max(busy.back().second, g.second);
            else
                busy.push_back(g);
        std::vector<double> took, hidden;
        double took_sum = 0, hidden_sum = 0;
        for (const Interval& b : bloom_) {
            uint64_t under = 0;
            for (const Interval& g : busy)
                if (g.second > b.first && g.first < b.second)
                    under += std::min(g.second, b.second) - std::max(g.first, b.first);
            took.push_back(ms(b.second - b.first));
            hidden.push_back(ms(under));
            took_sum += took.back();
            hidden_sum += hidden.back();
        }
        std::fprintf(stderr,
                     "overlap (--queues %s, %zu frames): bloom %.4f ms median, %.4f ms of it under "
                     "graphics work (%.0f%% of all bloom time)\n",
                     queues, took.size(), median(took), median(hidden),
                     took_sum > 0 ? 100.0 * hidden_sum / took_sum : 0.0);
        std::sort(shown_.begin(), shown_.end());
        std::vector<double> apart;
        for (size_t i = 1; i < shown_.size(); ++i) apart.push_back(ms(shown_[i] - shown_[i - 1]));
        if (!apart.empty())
            std::fprintf(stderr,
                         "gpu pace (--queues %s): a frame every %.4f ms (median time between "
                         "two tone maps' ends)\n",
                         queues, median(apart));
    }

private:
    using Interval = std::pair<uint64_t, uint64_t>;
    double ms(uint64_t ticks) const { return double(ticks) * double(period_) * 1e-6; }
    static double median(std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
        return v[v.size() / 2];
    }

    VkDevice device_ = VK_NULL_HANDLE;
    float period_ = 1.0f;  // nanoseconds per tick
    vkt::QueryPool pool_;
    std::vector<bool> written_;  // per slot: six marks recorded, not yet collected
    std::vector<Interval> graphics_, bloom_;
    std::vector<uint64_t> shown_;  // each tone map's end
};

}  // namespace ch29
