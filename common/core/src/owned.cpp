#include "vkt/core/owned.hpp"

#include "vkt/core/check.hpp"

namespace vkt {

Semaphore create_semaphore(VkDevice device) {
    VkSemaphoreCreateInfo info{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore;
    VKT_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
    return Semaphore(device, semaphore);
}

Fence create_fence(VkDevice device, bool signaled) {
    VkFenceCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO,
        .flags = signaled ? VkFenceCreateFlags{VK_FENCE_CREATE_SIGNALED_BIT} : 0u,
    };
    VkFence fence;
    VKT_CHECK(vkCreateFence(device, &info, nullptr, &fence));
    return Fence(device, fence);
}

CommandPool create_command_pool(VkDevice device, uint32_t queue_family,
                                VkCommandPoolCreateFlags flags) {
    VkCommandPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
        .flags = flags,
        .queueFamilyIndex = queue_family,
    };
    VkCommandPool pool;
    VKT_CHECK(vkCreateCommandPool(device, &info, nullptr, &pool));
    return CommandPool(device, pool);
}

}  // namespace vkt
