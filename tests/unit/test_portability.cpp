#include "vkt/core/device.hpp"
#include "vkt/core/portability.hpp"

#include <catch2/catch_test_macros.hpp>

#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

// A pretend loader or device: the list vkEnumerate*ExtensionProperties would give.
static std::vector<VkExtensionProperties> offering(std::vector<const char*> names) {
    std::vector<VkExtensionProperties> list(names.size());
    for (size_t i = 0; i < names.size(); ++i) {
        std::strncpy(list[i].extensionName, names[i], VK_MAX_EXTENSION_NAME_SIZE - 1);
        list[i].specVersion = 1;
    }
    return list;
}

static std::vector<std::string> strings(const std::vector<const char*>& names) {
    return {names.begin(), names.end()};
}

// Lavapipe's loader on Linux, and the loader on macOS with MoltenVK installed.
static const auto linux_loader = offering({"VK_KHR_surface", "VK_EXT_debug_utils"});
static const auto macos_loader =
    offering({"VK_KHR_surface", "VK_EXT_metal_surface", "VK_KHR_portability_enumeration"});
// A full Vulkan device and MoltenVK's.
static const auto full_device = offering({"VK_KHR_swapchain"});
static const auto moltenvk = offering({"VK_KHR_swapchain", "VK_KHR_portability_subset"});

TEST_CASE("offers finds an extension by its whole name", "[portability]") {
    CHECK(vkt::offers(macos_loader, "VK_KHR_portability_enumeration"));
    CHECK_FALSE(vkt::offers(linux_loader, "VK_KHR_portability_enumeration"));
    CHECK_FALSE(vkt::offers(macos_loader, "VK_KHR_portability"));
    CHECK_FALSE(vkt::offers({}, "VK_KHR_surface"));
}

TEST_CASE("the instance enables portability enumeration, with its flag, when offered",
          "[portability]") {
    const char* wanted[] = {"VK_KHR_surface", "VK_EXT_metal_surface"};
    const vkt::InstanceExtensions got = vkt::instance_extensions(macos_loader, wanted);
    CHECK(strings(got.names) == std::vector<std::string>{"VK_KHR_surface", "VK_EXT_metal_surface",
                                                         "VK_KHR_portability_enumeration"});
    CHECK(got.flags == VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR);

    // Asked for already: named once, and the flag still set.
    const char* twice[] = {"VK_KHR_portability_enumeration"};
    const vkt::InstanceExtensions again = vkt::instance_extensions(macos_loader, twice);
    CHECK(strings(again.names) == std::vector<std::string>{"VK_KHR_portability_enumeration"});
    CHECK(again.flags == VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR);
}

TEST_CASE("without portability enumeration the instance gets neither it nor the flag",
          "[portability]") {
    const char* wanted[] = {"VK_KHR_surface"};
    const vkt::InstanceExtensions got = vkt::instance_extensions(linux_loader, wanted);
    CHECK(strings(got.names) == std::vector<std::string>{"VK_KHR_surface"});
    CHECK(got.flags == 0);
    CHECK(vkt::instance_extensions({}, {}).names.empty());
}

TEST_CASE("the device enables the portability subset exactly when it offers it", "[portability]") {
    const char* wanted[] = {"VK_KHR_swapchain"};
    CHECK(strings(vkt::device_extensions(moltenvk, wanted)) ==
          std::vector<std::string>{"VK_KHR_swapchain", "VK_KHR_portability_subset"});
    CHECK(strings(vkt::device_extensions(full_device, wanted)) ==
          std::vector<std::string>{"VK_KHR_swapchain"});
    // Chapters 01 and 02 ask for no device extension at all.
    CHECK(strings(vkt::device_extensions(moltenvk, {})) ==
          std::vector<std::string>{"VK_KHR_portability_subset"});
    CHECK(vkt::device_extensions(full_device, {}).empty());
}

// MoltenVK as it describes itself on a Mac without triangle fans or events
// (which of the parts it has depends on the Mac and the release).
static VkPhysicalDevicePortabilitySubsetFeaturesKHR pretend_moltenvk() {
    VkPhysicalDevicePortabilitySubsetFeaturesKHR f{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PORTABILITY_SUBSET_FEATURES_KHR};
    f.constantAlphaColorBlendFactors = VK_TRUE;
    f.imageViewFormatReinterpretation = VK_TRUE;
    f.imageViewFormatSwizzle = VK_TRUE;
    f.samplerMipLodBias = VK_FALSE;
    f.triangleFans = VK_FALSE;
    f.events = VK_FALSE;
    return f;
}

TEST_CASE("a missing portability feature makes the device unsuitable, by name", "[portability]") {
    const vkt::PortabilityFeature needs[] = {VKT_PORTABILITY_FEATURE(imageViewFormatSwizzle),
                                             VKT_PORTABILITY_FEATURE(triangleFans)};
    CHECK(vkt::portability_shortfall(moltenvk, pretend_moltenvk(), needs) ==
          "lacks the triangleFans feature of VK_KHR_portability_subset");

    const vkt::PortabilityFeature has[] = {VKT_PORTABILITY_FEATURE(imageViewFormatSwizzle),
                                           VKT_PORTABILITY_FEATURE(constantAlphaColorBlendFactors)};
    CHECK(vkt::portability_shortfall(moltenvk, pretend_moltenvk(), has).empty());
    CHECK(vkt::portability_shortfall(moltenvk, pretend_moltenvk(), {}).empty());
}

TEST_CASE("a device without the portability subset has every part of Vulkan", "[portability]") {
    // Its features struct is never filled in (all VK_FALSE): it must not matter.
    const VkPhysicalDevicePortabilitySubsetFeaturesKHR unasked{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PORTABILITY_SUBSET_FEATURES_KHR};
    const vkt::PortabilityFeature needs[] = {VKT_PORTABILITY_FEATURE(triangleFans),
                                             VKT_PORTABILITY_FEATURE(events)};
    CHECK(vkt::portability_shortfall(full_device, unasked, needs).empty());
}

TEST_CASE("a hidden name hides a portability feature as it hides any other", "[portability]") {
    const vkt::PortabilityFeature needs[] = {VKT_PORTABILITY_FEATURE(samplerMipLodBias)};
    VkPhysicalDevicePortabilitySubsetFeaturesKHR all = pretend_moltenvk();
    all.samplerMipLodBias = VK_TRUE;
    const vkt::HiddenNames hidden{{"synchronization2", "samplerMipLodBias"}};
    // On any device, as the tests play a device without it on lavapipe.
    const std::string on_portability = vkt::portability_shortfall(moltenvk, all, needs, hidden);
    const std::string on_full = vkt::portability_shortfall(full_device, all, needs, hidden);
    const std::string core =
        vkt::lacks_feature("synchronization2", {}, hidden.hides("synchronization2"));
    CHECK(on_portability ==
          "lacks the samplerMipLodBias feature of VK_KHR_portability_subset"
          " (hidden by VKT_HIDE_FEATURES)");
    CHECK(on_full == on_portability);
    CHECK(core == "lacks the synchronization2 feature (hidden by VKT_HIDE_FEATURES)");
    CHECK(vkt::portability_shortfall(moltenvk, all, needs).empty());
}

TEST_CASE("the enabled portability features are exactly the required ones", "[portability]") {
    const vkt::PortabilityFeature needs[] = {VKT_PORTABILITY_FEATURE(events),
                                             VKT_PORTABILITY_FEATURE(pointPolygons)};
    const VkPhysicalDevicePortabilitySubsetFeaturesKHR on =
        vkt::portability_features_to_enable(needs);
    CHECK(on.sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PORTABILITY_SUBSET_FEATURES_KHR);
    CHECK(on.pNext == nullptr);
    CHECK(on.events == VK_TRUE);
    CHECK(on.pointPolygons == VK_TRUE);
    CHECK(on.triangleFans == VK_FALSE);
    CHECK(on.samplerMipLodBias == VK_FALSE);
    CHECK(std::string(VKT_PORTABILITY_FEATURE(triangleFans).name) == "triangleFans");
}
