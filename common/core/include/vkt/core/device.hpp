#pragma once
// The tidy form of chapter 02: look at every physical device, say why each one
// can or cannot run the chapter, pick the best (or the one --device names), and
// create a logical device with the Vulkan 1.3 features the tutorial relies on.

#include "vkt/core/check.hpp"
#include "vkt/core/hidden_names.hpp"
#include "vkt/core/portability.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

// One VkBool32 member of a feature struct: Vulkan 1.0's VkPhysicalDeviceFeatures
// or the Vulkan 1.1, 1.2 and 1.3 feature structs. Name them with the macros
// below, e.g. VKT_FEATURE_10(samplerAnisotropy), VKT_FEATURE_12(descriptorIndexing).
struct Feature {
    enum Set { core10, core11, core12, core13 };
    const char* name;
    Set set;
    size_t offset;  // of the VkBool32 member within its struct
};

#define VKT_FEATURE_10(member)                                                      \
    ::vkt::Feature {                                                                \
#member, ::vkt::Feature::core10, offsetof(VkPhysicalDeviceFeatures, member) \
    }
#define VKT_FEATURE_11(member)                                                              \
    ::vkt::Feature {                                                                        \
#member, ::vkt::Feature::core11, offsetof(VkPhysicalDeviceVulkan11Features, member) \
    }
#define VKT_FEATURE_12(member)                                                              \
    ::vkt::Feature {                                                                        \
#member, ::vkt::Feature::core12, offsetof(VkPhysicalDeviceVulkan12Features, member) \
    }
#define VKT_FEATURE_13(member)                                                              \
    ::vkt::Feature {                                                                        \
#member, ::vkt::Feature::core13, offsetof(VkPhysicalDeviceVulkan13Features, member) \
    }

// Chapter 02's feature chain: the four feature structs linked through pNext,
// for vkGetPhysicalDeviceFeatures2 (what a device has) and vkCreateDevice (what
// we turn on). Not copyable: the pNext pointers point into the object itself.
class FeatureChain {
public:
    FeatureChain();
    FeatureChain(const FeatureChain&) = delete;
    FeatureChain& operator=(const FeatureChain&) = delete;

    VkBool32& operator[](const Feature& feature);
    bool has(const Feature& feature) const;
    VkPhysicalDeviceFeatures2* head() { return &features_; }
    // Links `next` (extension feature structs) after the core ones, or unlinks them (nullptr).
    void link(void* next) { features13_.pNext = next; }

private:
    VkPhysicalDeviceFeatures2 features_{};
    VkPhysicalDeviceVulkan11Features features11_{};
    VkPhysicalDeviceVulkan12Features features12_{};
    VkPhysicalDeviceVulkan13Features features13_{};
};

// What every chapter needs (dynamicRendering and synchronization2).
std::span<const Feature> base_features();

struct DeviceRequirements {
    std::vector<const char*> extensions;  // device extensions, e.g. VK_KHR_swapchain
    // Features the chapter cannot run without: a device that lacks one is
    // unsuitable, and says which.
    std::vector<Feature> features;
    // Features the chapter uses when present (anisotropic filtering, say); it
    // asks Context::features whether it got them.
    std::vector<Feature> optional_features;
    // Parts of Vulkan a portability driver (MoltenVK) may lack that the chapter
    // uses, e.g. VKT_PORTABILITY_FEATURE(triangleFans): a portability device
    // without one is unsuitable, and says which (vkt/core/portability.hpp).
    std::vector<PortabilityFeature> portability_features;
    // Feature structs of extensions (VkPhysicalDevice...FeaturesEXT/KHR, their
    // members set to what is wanted), linked through their pNext: appended to
    // the feature chain that vkCreateDevice is given. The caller keeps them alive
    // until the Device is created, and names their extensions above.
    void* extension_features = nullptr;
    HiddenNames hidden;  // pretended missing (the tests' devices)
    // Chapter 29's second queue: also one queue of a family that computes but
    // cannot draw, where the device has such a family (Device::compute_queue).
    bool compute_family = false;
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

// How a device's verdict names a missing feature: "lacks the dynamicRendering
// feature", or with `of`, "lacks the triangleFans feature of
// VK_KHR_portability_subset"; " (hidden by VKT_HIDE_FEATURES)" follows when a
// test hid it.
std::string lacks_feature(std::string_view name, std::string_view of = {}, bool hidden = false);

// Discrete GPUs first, then integrated, virtual, and software rasterisers last.
int device_type_score(VkPhysicalDeviceType type);
// The score chapter 02 prints: the type first, then the largest image size.
int device_score(const DeviceCandidate& candidate);

// Whether the device has VK_KHR_swapchain and its queue family can present to
// the surface. A query that fails (some loaders answer a surface of an
// extension the driver lacks with an error) counts as "no".
bool can_present(VkPhysicalDevice device, uint32_t queue_family, VkSurfaceKHR surface);

// Chapter 29: the first queue family that computes but cannot draw (the
// "async compute" family some GPUs have), or UINT32_MAX where there is none.
uint32_t compute_only_family(VkPhysicalDevice device);

// Whether the device offers the extension.
bool device_extension_available(VkPhysicalDevice device, const char* name);

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
    // Chapter 29's: a queue of a compute-only family where the requirements
    // asked for one and the device has one; else queue() and its family.
    VkQueue compute_queue() const { return compute_queue_; }
    uint32_t compute_family() const { return compute_family_; }
    const VkPhysicalDeviceProperties& properties() const { return properties_; }
    // Exactly the features that were enabled: the base ones, the required ones,
    // and the optional ones the device has.
    const FeatureChain& features() const { return enabled_; }

private:
    FeatureChain enabled_;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    VkQueue compute_queue_ = VK_NULL_HANDLE;
    uint32_t compute_family_ = 0;
    VkPhysicalDeviceProperties properties_{};
};

}  // namespace vkt
