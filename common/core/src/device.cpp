#include "vkt/core/device.hpp"
#include "vkt/core/extension_features.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

namespace vkt {

FeatureChain::FeatureChain() {
    features13_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
    features12_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    features12_.pNext = &features13_;
    features11_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES;
    features11_.pNext = &features12_;
    features_.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    features_.pNext = &features11_;
}

VkBool32& FeatureChain::operator[](const Feature& feature) {
    const auto member = [&](auto& features) -> VkBool32& {
        return *reinterpret_cast<VkBool32*>(reinterpret_cast<std::byte*>(&features) +
                                            feature.offset);
    };
    switch (feature.set) {
        case Feature::core10:
            return member(features_.features);
        case Feature::core11:
            return member(features11_);
        case Feature::core12:
            return member(features12_);
        case Feature::core13:
            return member(features13_);
    }
    throw Error("FeatureChain: feature " + std::string(feature.name) + " names no feature set");
}

bool FeatureChain::has(const Feature& feature) const {
    // operator[] finds the field; here it is only read, so casting away const
    // is safe, and one lookup serves both.
    return const_cast<FeatureChain&>(*this)[feature] ==  // NOLINT(*-pro-type-const-cast)
           VK_TRUE;
}

std::span<const Feature> base_features() {
    static const Feature base[] = {VKT_FEATURE_13(dynamicRendering),
                                   VKT_FEATURE_13(synchronization2)};
    return base;
}

int device_score(const DeviceCandidate& candidate) {
    return 1000 * device_type_score(candidate.type) + int(candidate.max_image_dimension / 1024);
}

static std::vector<VkExtensionProperties> extensions_of(VkPhysicalDevice device) {
    uint32_t count = 0;
    VKT_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> offered(count);
    VKT_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, offered.data()));
    offered.resize(count);
    return offered;
}

bool can_present(VkPhysicalDevice device, uint32_t queue_family, VkSurfaceKHR surface) {
    if (!offers(extensions_of(device), VK_KHR_SWAPCHAIN_EXTENSION_NAME)) return false;
    VkBool32 supported = VK_FALSE;
    return vkGetPhysicalDeviceSurfaceSupportKHR(device, queue_family, surface, &supported) ==
               VK_SUCCESS &&
           supported;
}

bool device_extension_available(VkPhysicalDevice device, const char* name) {
    return offers(extensions_of(device), name);
}

int device_type_score(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 4;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 3;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 1;
        default:
            return 0;
    }
}

std::string lacks_feature(std::string_view name, std::string_view of, bool hidden) {
    return "lacks the " + std::string(name) + " feature" +
           (of.empty() ? "" : " of " + std::string(of)) +
           (hidden ? " (hidden by VKT_HIDE_FEATURES)" : "");
}

// "lacks the extension VK_KHR_swapchain"
static std::string lacks_extension(std::string_view name, bool hidden) {
    return "lacks the extension " + std::string(name) +
           (hidden ? " (hidden by VKT_HIDE_FEATURES)" : "");
}

// What a portability device has of the parts VK_KHR_portability_subset names;
// asked only where the device offers the extension.
static VkPhysicalDevicePortabilitySubsetFeaturesKHR portability_features_of(
    VkPhysicalDevice device, std::span<const VkExtensionProperties> offered) {
    VkPhysicalDevicePortabilitySubsetFeaturesKHR subset{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PORTABILITY_SUBSET_FEATURES_KHR};
    if (!offers(offered, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME)) return subset;
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                       .pNext = &subset};
    vkGetPhysicalDeviceFeatures2(device, &features);
    subset.pNext = nullptr;
    return subset;
}

static std::string why_unsuitable(VkPhysicalDevice device, VkSurfaceKHR surface,
                                  const DeviceRequirements& requirements, uint32_t& family_out) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_3)
        return "supports only Vulkan " +
               std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
               std::to_string(VK_API_VERSION_MINOR(properties.apiVersion)) + ", not 1.3";

    const HiddenNames& hidden = requirements.hidden;
    FeatureChain available;
    vkGetPhysicalDeviceFeatures2(device, available.head());
    for (std::span<const Feature> needed : {base_features(), std::span(requirements.features)})
        for (const Feature& feature : needed)
            if (!available.has(feature) || hidden.hides(feature.name))
                return lacks_feature(feature.name, {}, hidden.hides(feature.name));

    const std::vector<VkExtensionProperties> offered = extensions_of(device);
    for (const char* wanted : requirements.extensions)
        if (!offers(offered, wanted) || hidden.hides(wanted))
            return lacks_extension(wanted, hidden.hides(wanted));
    // The features of those extensions that the chapter turns on
    // (vkt/core/extension_features.hpp): asked only now that the device is
    // known to offer the extensions.
    if (std::string missing =
            extension_feature_shortfall(device, requirements.extension_features, hidden);
        !missing.empty())
        return missing;
    std::string shortfall = portability_shortfall(offered, portability_features_of(device, offered),
                                                  requirements.portability_features, hidden);
    if (!shortfall.empty()) return shortfall;

    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & wanted) != wanted) continue;
        if (surface && !can_present(device, i, surface)) continue;
        family_out = i;
        return {};
    }
    return surface ? "has no queue family that can draw, compute and present to this surface"
                   : "has no queue family that can draw and compute";
}

std::vector<DeviceCandidate> survey_devices(VkInstance instance, VkSurfaceKHR surface,
                                            const DeviceRequirements& requirements) {
    uint32_t count = 0;
    VKT_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VKT_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));

    std::vector<DeviceCandidate> candidates;
    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(devices[i], &properties);
        DeviceCandidate candidate{
            .handle = devices[i],
            .index = i,
            .name = properties.deviceName,
            .type = properties.deviceType,
            .api_version = properties.apiVersion,
            .max_image_dimension = properties.limits.maxImageDimension2D,
        };
        candidate.unsuitable =
            why_unsuitable(devices[i], surface, requirements, candidate.queue_family);
        candidates.push_back(std::move(candidate));
    }
    return candidates;
}

static std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

const DeviceCandidate& choose_device(std::span<const DeviceCandidate> candidates,
                                     std::string_view selector) {
    if (candidates.empty())
        throw Error(
            "no Vulkan device found: is a Vulkan driver installed? "
            "(on Debian: apt install mesa-vulkan-drivers)");

    if (!selector.empty()) {
        const DeviceCandidate* named = nullptr;
        // All digits: an index (however large); anything else: part of a name.
        if (std::all_of(selector.begin(), selector.end(),
                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
            uint64_t index = UINT64_MAX;
            std::from_chars(selector.data(), selector.data() + selector.size(), index);
            if (index >= candidates.size())
                throw Error("--device " + std::string(selector) + ": there are only " +
                            std::to_string(candidates.size()) + " device(s), numbered from 0");
            named = &candidates[index];
        } else {
            for (const auto& candidate : candidates)
                if (lower(candidate.name).find(lower(selector)) != std::string::npos) {
                    named = &candidate;
                    break;
                }
            if (!named)
                throw Error("--device " + std::string(selector) +
                            ": no device has that in its name");
        }
        if (!named->unsuitable.empty())
            throw Error("device " + std::to_string(named->index) + " (" + named->name + ") " +
                        named->unsuitable);
        return *named;
    }

    const DeviceCandidate* best = nullptr;
    for (const auto& candidate : candidates)
        if (candidate.unsuitable.empty() &&
            (!best || device_score(candidate) > device_score(*best)))
            best = &candidate;
    if (!best) {
        std::string reasons;
        for (const auto& candidate : candidates)
            reasons += "; " + candidate.name + " " + candidate.unsuitable;
        throw Error("no Vulkan device can run this chapter" + reasons);
    }
    return *best;
}

uint32_t compute_only_family(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i)
        if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) &&
            !(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT))
            return i;
    return UINT32_MAX;
}

Device::Device(const DeviceCandidate& chosen, const DeviceRequirements& requirements)
    : physical_(chosen.handle), queue_family_(chosen.queue_family) {
    vkGetPhysicalDeviceProperties(physical_, &properties_);

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_infos[2]{};
    queue_infos[0] = {
        .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
        .queueFamilyIndex = queue_family_,
        .queueCount = 1,
        .pQueuePriorities = &priority,
    };
    compute_family_ = requirements.compute_family ? compute_only_family(physical_) : UINT32_MAX;
    if (compute_family_ == UINT32_MAX) compute_family_ = queue_family_;  // none: the one queue
    queue_infos[1] = queue_infos[0];
    queue_infos[1].queueFamilyIndex = compute_family_;
    // Turn on exactly what is needed: the base features, the chapter's required
    // ones, and those optional ones this device has.
    FeatureChain available;
    vkGetPhysicalDeviceFeatures2(physical_, available.head());
    for (const Feature& feature : base_features()) enabled_[feature] = VK_TRUE;
    for (const Feature& feature : requirements.features) enabled_[feature] = VK_TRUE;
    for (const Feature& feature : requirements.optional_features)
        enabled_[feature] =
            available.has(feature) && !requirements.hidden.hides(feature.name) ? VK_TRUE : VK_FALSE;
    // On a portability driver (MoltenVK): VK_KHR_portability_subset, which must
    // be enabled where offered, and the parts of it the chapter uses.
    const std::vector<VkExtensionProperties> offered = extensions_of(physical_);
    const std::vector<const char*> extensions = device_extensions(offered, requirements.extensions);
    VkPhysicalDevicePortabilitySubsetFeaturesKHR subset =
        portability_features_to_enable(requirements.portability_features);
    subset.pNext = enabled_.head();
    const void* chain = enabled_.head();
    if (offers(offered, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME)) chain = &subset;
    VkDeviceCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = chain,
        .queueCreateInfoCount = compute_family_ == queue_family_ ? 1u : 2u,
        .pQueueCreateInfos = queue_infos,
        .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
        .ppEnabledExtensionNames = extensions.data(),
    };
    enabled_.link(requirements.extension_features);
    VKT_CHECK(vkCreateDevice(physical_, &info, nullptr, &device_));
    enabled_.link(nullptr);  // those structs are the caller's, and may go now
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);
    vkGetDeviceQueue(device_, compute_family_, 0, &compute_queue_);
}

Device::~Device() {
    if (device_) vkDestroyDevice(device_, nullptr);
}

}  // namespace vkt
