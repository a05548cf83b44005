#include "vkt/gpu_timer.hpp"

#include "vkt/check.hpp"

namespace vkt {

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
        .queryCount = 2 * slots,
    };
    VkQueryPool pool;
    VKT_CHECK(vkCreateQueryPool(device, &info, nullptr, &pool));
    pool_ = QueryPool(device, pool);
    pending_.assign(slots, false);
}

void GpuTimer::begin(VkCommandBuffer cmd, uint32_t slot) {
    if (!pool_) return;
    vkCmdResetQueryPool(cmd, pool_, 2 * slot, 2);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * slot);
}

void GpuTimer::end(VkCommandBuffer cmd, uint32_t slot) {
    if (!pool_) return;
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 2 * slot + 1);
    pending_[slot] = true;
}

void GpuTimer::collect(uint32_t slot) {
    if (!pool_ || !pending_[slot]) return;
    pending_[slot] = false;
    uint64_t ticks[2];
    VKT_CHECK(vkGetQueryPoolResults(device_, pool_, 2 * slot, 2, sizeof ticks, ticks,
                                    sizeof(uint64_t),
                                    VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const uint64_t elapsed = (ticks[1] - ticks[0]) & mask_;
    samples_.push_back(double(elapsed) * period_ns_ / 1e6);
}

}  // namespace vkt
