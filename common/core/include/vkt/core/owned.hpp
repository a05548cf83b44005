#pragma once
// Move-only owners for Vulkan handles. Taught in chapter 01 (every vkCreate has
// its vkDestroy, in reverse order): an owner destroys its handle exactly once,
// when it goes out of scope. C++ destroys members in reverse order of
// declaration, so declaring parents before children gives the order Vulkan
// wants (move assignment goes in declaration order; see vkt::Image).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <type_traits>
#include <utility>

namespace vkt {

// Owns a handle created from a parent (usually the VkDevice) and destroyed with
// Destroy(parent, handle, nullptr). Destroy is a vkDestroy function, taken by
// reference: in the Windows build it is volk's function pointer of that name
// (cmake/windows.cmake), read when the handle is destroyed.
template <typename Handle, typename Parent, auto& Destroy>
class Owned {
    static_assert(std::is_invocable_r_v<void, decltype(Destroy), Parent, Handle,
                                        const VkAllocationCallbacks*>);

public:
    Owned() = default;
    Owned(Parent parent, Handle handle) : parent_(parent), handle_(handle) {}
    ~Owned() { reset(); }

    Owned(const Owned&) = delete;
    Owned& operator=(const Owned&) = delete;
    Owned(Owned&& other) noexcept
        : parent_(other.parent_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
    Owned& operator=(Owned&& other) noexcept {
        if (this != &other) {
            reset();
            parent_ = other.parent_;
            handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
        }
        return *this;
    }

    void reset() {
        if (handle_ != VK_NULL_HANDLE)
            Destroy(parent_, std::exchange(handle_, VK_NULL_HANDLE), nullptr);
    }
    Handle get() const { return handle_; }
    operator Handle() const { return handle_; }  // NOLINT: pass straight to vk* calls
    explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

private:
    Parent parent_ = VK_NULL_HANDLE;
    Handle handle_ = VK_NULL_HANDLE;
};

using Semaphore = Owned<VkSemaphore, VkDevice, vkDestroySemaphore>;
using Fence = Owned<VkFence, VkDevice, vkDestroyFence>;
using CommandPool = Owned<VkCommandPool, VkDevice, vkDestroyCommandPool>;
using ImageView = Owned<VkImageView, VkDevice, vkDestroyImageView>;
using ShaderModule = Owned<VkShaderModule, VkDevice, vkDestroyShaderModule>;
using PipelineLayout = Owned<VkPipelineLayout, VkDevice, vkDestroyPipelineLayout>;
using Pipeline = Owned<VkPipeline, VkDevice, vkDestroyPipeline>;
using QueryPool = Owned<VkQueryPool, VkDevice, vkDestroyQueryPool>;
using SwapchainHandle = Owned<VkSwapchainKHR, VkDevice, vkDestroySwapchainKHR>;
using SurfaceHandle = Owned<VkSurfaceKHR, VkInstance, vkDestroySurfaceKHR>;
using DeviceMemory = Owned<VkDeviceMemory, VkDevice, vkFreeMemory>;
using BufferHandle = Owned<VkBuffer, VkDevice, vkDestroyBuffer>;
using ImageHandle = Owned<VkImage, VkDevice, vkDestroyImage>;
using DescriptorSetLayout = Owned<VkDescriptorSetLayout, VkDevice, vkDestroyDescriptorSetLayout>;
using DescriptorPool = Owned<VkDescriptorPool, VkDevice, vkDestroyDescriptorPool>;
using Sampler = Owned<VkSampler, VkDevice, vkDestroySampler>;

// Small constructors for the objects every frame loop needs.
Semaphore create_semaphore(VkDevice device);
Fence create_fence(VkDevice device, bool signaled);
CommandPool create_command_pool(VkDevice device, uint32_t queue_family,
                                VkCommandPoolCreateFlags flags);

}  // namespace vkt
