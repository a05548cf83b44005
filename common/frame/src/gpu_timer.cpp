#include "vkt/frame/gpu_timer.hpp"

#include "vkt/core/check.hpp"

namespace vkt {

namespace {
constexpr uint32_t tracks = 1 + GpuTimer::max_scopes;  // the frame, then the scopes
}

GpuTimer::GpuTimer(VkPhysicalDevice physical, VkDevice device, uint32_t queue_family,
                   uint32_t slots)
    : device_(device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical, &properties);
    const uint32_t bits = families.at(queue_family).timestampValidBits;
    if (bits == 0 || properties.limits.timestampPeriod <= 0) return;  // no timestamps here
    mask_ = bits >= 64 ? ~0ull : (1ull << bits) - 1;
    period_ns_ = properties.limits.timestampPeriod;
    VkQueryPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
        .queryType = VK_QUERY_TYPE_TIMESTAMP,
        .queryCount = 2 * tracks * slots,
    };
    VkQueryPool pool;
    VKT_CHECK(vkCreateQueryPool(device, &info, nullptr, &pool));
    pool_ = QueryPool(device, pool);
    pending_.assign(slots, std::vector<bool>(tracks, false));
    open_.assign(slots, std::vector<bool>(tracks, false));
}

uint32_t GpuTimer::first_query(uint32_t slot, uint32_t track) const {
    return 2 * (slot * tracks + track);
}

void GpuTimer::begin(VkCommandBuffer cmd, uint32_t slot) {
    if (!pool_) return;
    // Every query of the slot is reset here, before any is written this frame.
    vkCmdResetQueryPool(cmd, pool_, first_query(slot, 0), 2 * tracks);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, first_query(slot, 0));
}

void GpuTimer::end(VkCommandBuffer cmd, uint32_t slot) {
    if (!pool_) return;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_,
                         first_query(slot, 0) + 1);
    pending_[slot][0] = true;
}

uint32_t GpuTimer::scope_index(std::string_view name) {
    for (uint32_t i = 0; i < scopes_.size(); ++i)
        if (scopes_[i].name == name) return i;
    if (scopes_.size() == max_scopes)
        throw Error("GpuTimer: more than " + std::to_string(max_scopes) + " named scopes");
    scopes_.push_back({std::string(name), {}});
    return uint32_t(scopes_.size() - 1);
}

void GpuTimer::begin_scope(VkCommandBuffer cmd, uint32_t slot, std::string_view name) {
    if (!pool_) return;
    const uint32_t track = 1 + scope_index(name);
    if (open_[slot][track] || pending_[slot][track])
        throw Error("GpuTimer: scope '" + std::string(name) + "' timed twice in one frame");
    open_[slot][track] = true;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_,
                         first_query(slot, track));
}

void GpuTimer::end_scope(VkCommandBuffer cmd, uint32_t slot, std::string_view name) {
    if (!pool_) return;
    const uint32_t track = 1 + scope_index(name);
    if (!open_[slot][track]) return;
    open_[slot][track] = false;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_,
                         first_query(slot, track) + 1);
    pending_[slot][track] = true;
}

void GpuTimer::read(uint32_t slot, uint32_t track, std::vector<double>& out) {
    uint64_t ticks[2];
    VKT_CHECK(vkGetQueryPoolResults(device_, pool_, first_query(slot, track), 2, sizeof ticks,
                                    ticks, sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint64_t elapsed = (ticks[1] - ticks[0]) & mask_;
    out.push_back(double(elapsed) * period_ns_ / 1e6);
}

void GpuTimer::collect(uint32_t slot) {
    if (!pool_) return;
    for (uint32_t track = 0; track < tracks; ++track) {
        if (!pending_[slot][track]) continue;
        pending_[slot][track] = false;
        read(slot, track, track == 0 ? frame_.samples : scopes_[track - 1].samples);
    }
}

}  // namespace vkt
