#include "vkt/core/portability.hpp"

#include "vkt/core/device.hpp"

#include <algorithm>
#include <cstring>

namespace vkt {

bool offers(std::span<const VkExtensionProperties> offered, std::string_view name) {
    return std::any_of(offered.begin(), offered.end(), [&](const VkExtensionProperties& e) {
        return name == std::string_view(e.extensionName);
    });
}

// The wanted names, then `extra` unless it is among them already.
static std::vector<const char*> with(std::span<const char* const> wanted, const char* extra) {
    std::vector<const char*> names(wanted.begin(), wanted.end());
    if (std::none_of(names.begin(), names.end(),
                     [&](const char* name) { return std::strcmp(name, extra) == 0; }))
        names.push_back(extra);
    return names;
}

InstanceExtensions instance_extensions(std::span<const VkExtensionProperties> offered,
                                       std::span<const char* const> wanted) {
    if (!offers(offered, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME))
        return {.names = {wanted.begin(), wanted.end()}};
    // The extension and the flag go together: the flag without the extension
    // is invalid, the extension without the flag lists nothing more.
    return {.names = with(wanted, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME),
            .flags = VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR};
}

std::vector<const char*> device_extensions(std::span<const VkExtensionProperties> offered,
                                           std::span<const char* const> wanted) {
    if (!offers(offered, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME))
        return {wanted.begin(), wanted.end()};
    return with(wanted, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME);
}

std::string portability_shortfall(std::span<const VkExtensionProperties> offered,
                                  const VkPhysicalDevicePortabilitySubsetFeaturesKHR& available,
                                  std::span<const PortabilityFeature> required,
                                  const HiddenNames& hidden) {
    const bool portability = offers(offered, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME);
    for (const PortabilityFeature& feature : required)
        if ((portability && available.*feature.member != VK_TRUE) || hidden.hides(feature.name))
            return lacks_feature(feature.name, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME,
                                 hidden.hides(feature.name));
    return {};
}

VkPhysicalDevicePortabilitySubsetFeaturesKHR portability_features_to_enable(
    std::span<const PortabilityFeature> required) {
    VkPhysicalDevicePortabilitySubsetFeaturesKHR enabled{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PORTABILITY_SUBSET_FEATURES_KHR};
    for (const PortabilityFeature& feature : required) enabled.*feature.member = VK_TRUE;
    return enabled;
}

}  // namespace vkt
