#pragma once
// The tidy form of chapter 02: look at every physical device, say why each one
// can or cannot run the chapter, pick the best (or the one --device names), and
// create a logical device with the Vulkan 1.3 features the tutorial relies on.

#include "vkt/check.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

struct DeviceRequirements {
    std::vector<const char*> extensions;  // device extensions, e.g. VK_KHR_swapchain
};

// What we learned about one physical device.
struct DeviceCandidate {
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    uint32_t index = 0;  // position in vkEnumeratePhysicalDevices, what --device N means
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    uint32_t api_version = 0;
    uint32_t max_image_dimension = 0;  // limits.maxImageDimension2D: the tie-break
    uint32_t queue_family = 0;         // graphics + compute (+ present, with a surface)
    std::string unsuitable;            // empty when the device can run the chapter
};

// Discrete GPUs first, then integrated, virtual, and software rasterisers last.
int device_type_score(VkPhysicalDeviceType type);
// The score chapter 02 prints: the type first, then the largest image size.
int device_score(const DeviceCandidate& candidate);

// Whether the device has VK_KHR_swapchain and its queue family can present to
// the surface. A query that fails (some loaders answer a surface of an
// extension the driver lacks with an error) counts as "no".
bool can_present(VkPhysicalDevice device, uint32_t queue_family, VkSurfaceKHR surface);

// Everything vkEnumeratePhysicalDevices reports, each with its verdict.
// surface may be VK_NULL_HANDLE (offscreen: no present support needed).
std::vector<DeviceCandidate> survey_devices(VkInstance instance, VkSurfaceKHR surface,
                                            const DeviceRequirements& requirements);

// The device --device names (an index or part of a name, any case), or else the
// suitable one with the best score. Throws Error with a plain explanation.
const DeviceCandidate& choose_device(std::span<const DeviceCandidate> candidates,
                                     std::string_view selector);

class Device {
public:
    Device(const DeviceCandidate& chosen, const DeviceRequirements& requirements);
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkDevice get() const { return device_; }
    operator VkDevice() const { return device_; }  // NOLINT
    VkPhysicalDevice physical() const { return physical_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }

private:
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    VkPhysicalDeviceProperties properties_{};
};

}  // namespace vkt
