#pragma once
// The tidy form of chapter 01: a VkInstance with, when asked, the Khronos
// validation layer (synchronisation validation included) and a debug messenger
// that prints every warning and error and counts them.

#include "vkt/core/check.hpp"

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace vkt {

inline constexpr const char* validation_layer_name = "VK_LAYER_KHRONOS_validation";

bool instance_layer_available(const char* name);
// The layer's Vulkan version (VkLayerProperties::specVersion), 0 if not installed.
uint32_t instance_layer_version(const char* name);
bool instance_extension_available(const char* name);

// Counts what the validation layer reported. A chapter run that saw any
// warning or error exits non-zero, so a test cannot pass over a message.
struct ValidationCounts {
    std::atomic<uint32_t> warnings{0};
    std::atomic<uint32_t> errors{0};
};

struct InstanceConfig {
    std::string application_name;
    bool validation = false;
    std::vector<const char*> extensions;  // e.g. VK_KHR_surface and a platform surface
};

class Instance {
public:
    explicit Instance(const InstanceConfig& config);
    ~Instance();
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    VkInstance get() const { return instance_; }
    operator VkInstance() const { return instance_; }  // NOLINT
    bool validation() const { return messenger_ != VK_NULL_HANDLE; }
    // Shared, so the counts can be read after the instance (and with it the
    // last chance for a message) is gone.
    std::shared_ptr<const ValidationCounts> counts() const { return counts_; }

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    std::shared_ptr<ValidationCounts> counts_ = std::make_shared<ValidationCounts>();
};

// The create-info of the debug messenger; it also goes into the pNext of
// VkInstanceCreateInfo so that vkCreateInstance itself is checked.
VkDebugUtilsMessengerCreateInfoEXT messenger_create_info(ValidationCounts* counts);

}  // namespace vkt
