#pragma once
// Chapter 19's --benchmark count of vertex shader invocations per frame: a
// pipeline statistics query, one per frame in flight. Set against the
// indices drawn and the vertices in the scene, it shows how many shaded
// vertices the post-transform cache reused (--edge-order vertex or axis).

#include "vkt/core/check.hpp"
#include "vkt/core/owned.hpp"

#include <vector>

namespace ch19 {

class InvocationCounter {
public:
    InvocationCounter() = default;  // counts nothing: every call does nothing

    // Needs the pipelineStatisticsQuery feature.
    InvocationCounter(VkDevice device, uint32_t frames_in_flight)
        : device_(device), issued_(frames_in_flight, false) {
        const VkQueryPoolCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
            .queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS,
            .queryCount = frames_in_flight,
            .pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT,
        };
        VkQueryPool pool = VK_NULL_HANDLE;
        VKT_CHECK(vkCreateQueryPool(device, &info, nullptr, &pool));
        pool_ = vkt::QueryPool(device, pool);
    }

    // At the start of a frame's commands, before begin(): keeps the count
    // this slot's previous frame left (its fence has been waited for, so
    // the count is ready) and resets the slot's query for this frame.
    void start_frame(VkCommandBuffer cmd, uint32_t slot) {
        if (!pool_) return;
        if (issued_[slot]) {
            uint64_t count = 0;
            VKT_CHECK(vkGetQueryPoolResults(device_, pool_, slot, 1, sizeof(count), &count,
                                            sizeof(count), VK_QUERY_RESULT_64_BIT));
            counts_.push_back(double(count));
        }
        vkCmdResetQueryPool(cmd, pool_, slot, 1);
    }

    // Around the draws to count, inside the frame's rendering.
    void begin(VkCommandBuffer cmd, uint32_t slot) const {
        if (pool_) vkCmdBeginQuery(cmd, pool_, slot, 0);
    }
    void end(VkCommandBuffer cmd, uint32_t slot) {
        if (!pool_) return;
        vkCmdEndQuery(cmd, pool_, slot);
        issued_[slot] = true;
    }

    // Every frame's count, once the device is idle (the runner waits for it
    // before the renderer is destroyed): the last count of each slot too.
    std::vector<double> finish() {
        for (size_t slot = 0; slot < issued_.size(); ++slot) {
            uint64_t count = 0;
            if (issued_[slot] &&
                vkGetQueryPoolResults(device_, pool_, uint32_t(slot), 1, sizeof(count), &count,
                                      sizeof(count), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS)
                counts_.push_back(double(count));
            issued_[slot] = false;
        }
        return counts_;
    }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    vkt::QueryPool pool_;
    std::vector<bool> issued_;    // [slot]: a query was ended and not yet read
    std::vector<double> counts_;  // per frame, in the order read
};

}  // namespace ch19
