#pragma once
// Portability drivers, taught in chapters 01 and 02. MoltenVK (Vulkan on
// Apple's Metal) implements nearly all of Vulkan, but not all of it; it is a
// "portability" driver. The loader lists such a driver only to a program that
// enables VK_KHR_portability_enumeration and sets
// VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR, and a device that offers
// VK_KHR_portability_subset must have that extension enabled (the
// specification requires it). Its features struct says which of the missing
// parts (triangle fans, events, ...) the device has after all.
//
// The decisions are pure functions of what the loader and the device offer,
// so the tests can play a MoltenVK device on any machine.

// VK_KHR_portability_subset is a provisional extension: vulkan.h declares its
// features struct and structure type only with VK_ENABLE_BETA_EXTENSIONS,
// which vkt_core passes to everything that links it (common/CMakeLists.txt).
#ifndef VK_ENABLE_BETA_EXTENSIONS
#error "vkt/core/portability.hpp needs VK_ENABLE_BETA_EXTENSIONS (link vkt_core)"
#endif

#include "vkt/core/check.hpp"
#include "vkt/core/hidden_names.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

// Whether a list from vkEnumerate*ExtensionProperties names the extension.
bool offers(std::span<const VkExtensionProperties> offered, std::string_view name);

// What vkCreateInstance gets: the extensions asked for, plus
// VK_KHR_portability_enumeration with its flag where the loader offers it.
struct InstanceExtensions {
    std::vector<const char*> names;
    VkInstanceCreateFlags flags = 0;
};
InstanceExtensions instance_extensions(std::span<const VkExtensionProperties> offered,
                                       std::span<const char* const> wanted);

// What vkCreateDevice gets: the extensions asked for, plus
// VK_KHR_portability_subset where the device offers it.
std::vector<const char*> device_extensions(std::span<const VkExtensionProperties> offered,
                                           std::span<const char* const> wanted);

// One VkBool32 member of VkPhysicalDevicePortabilitySubsetFeaturesKHR, named
// with VKT_PORTABILITY_FEATURE(triangleFans): a part of Vulkan that a chapter
// uses and a portability driver may lack. Any other device has them all.
struct PortabilityFeature {
    const char* name;
    VkBool32 VkPhysicalDevicePortabilitySubsetFeaturesKHR::*member;
};
#define VKT_PORTABILITY_FEATURE(member)                                \
    ::vkt::PortabilityFeature {                                        \
#member, &VkPhysicalDevicePortabilitySubsetFeaturesKHR::member \
    }

// Why the device cannot run a chapter that needs these portability features:
// "lacks the triangleFans feature of VK_KHR_portability_subset", as
// survey_devices says it of any other missing feature (a name in
// `hidden` counts as missing on any device). Empty when nothing is missing,
// and always on a device that does not offer the extension.
std::string portability_shortfall(std::span<const VkExtensionProperties> offered,
                                  const VkPhysicalDevicePortabilitySubsetFeaturesKHR& available,
                                  std::span<const PortabilityFeature> required,
                                  const HiddenNames& hidden = {});

// The features struct with exactly the required members on, for the pNext
// chain of VkDeviceCreateInfo (the struct is in the chain only where the device
// offers the extension).
VkPhysicalDevicePortabilitySubsetFeaturesKHR portability_features_to_enable(
    std::span<const PortabilityFeature> required);

}  // namespace vkt
