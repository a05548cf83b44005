// Chapter 01: the Vulkan instance.
//
// The instance is our connection to the Vulkan loader. Creating one means
// saying which API version we want, which layers to insert between us and the
// driver (the validation layer), and which instance extensions to switch on
// (debug utils, so the validation layer can talk to us). Then we list what
// the instance can see: the physical devices.

#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

// [debug-callback]
// The validation layer calls this for every message it has. We print
// warnings and errors and count them: a run with any of them has a bug.
struct MessageCounts {
    uint32_t warnings = 0;
    uint32_t errors = 0;
};

VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                          VkDebugUtilsMessageTypeFlagsEXT,
                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                          void* user) {
    auto* counts = static_cast<MessageCounts*>(user);
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    ++(error ? counts->errors : counts->warnings);
    std::fprintf(stderr, "[validation %s] %s\n", error ? "error" : "warning", data->pMessage);
    return VK_FALSE;  // VK_TRUE would make the offending call fail; we only report
}
// [/debug-callback]

std::string version_text(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

bool has_layer(const std::vector<VkLayerProperties>& layers, const char* name) {
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

bool has_extension(const std::vector<VkExtensionProperties>& extensions, const char* name) {
    for (const auto& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

int run(const vkt::Options& options) {
    // [instance-version]
    // vkEnumerateInstanceVersion is a Vulkan 1.1 function: the loader's version,
    // the highest API version an instance can have here.
    uint32_t loader_version = 0;
    VKT_CHECK(vkEnumerateInstanceVersion(&loader_version));
    std::printf("Vulkan instance version: %s\n", version_text(loader_version).c_str());
    // [/instance-version]

    // [enumerate]
    // The two-call idiom: ask for the count, size the array, ask for the data.
    uint32_t count = 0;
    VKT_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VKT_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    std::printf("\n%zu instance layers:\n", layers.size());
    for (const auto& layer : layers)
        std::printf("  %-40s %s\n", layer.layerName, layer.description);

    VKT_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VKT_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data()));
    std::printf("\n%zu instance extensions:\n", extensions.size());
    for (const auto& extension : extensions) std::printf("  %s\n", extension.extensionName);
    // [/enumerate]

    // [choose-validation]
    // Validation is on when asked for, and by default whenever the layer is
    // installed; asking for it without the layer is an error, not a shrug.
    const char* validation_layer = "VK_LAYER_KHRONOS_validation";
    const bool installed = has_layer(layers, validation_layer);
    if (options.validation.value_or(false) && !installed)
        throw vkt::Error(
            "--validation: VK_LAYER_KHRONOS_validation is not installed "
            "(on Debian: apt install vulkan-validationlayers)");
    const bool validation = options.validation.value_or(installed);
    // [/choose-validation]

    // [portability]
    // MoltenVK (Vulkan on Apple's Metal) lacks a few parts of Vulkan, so it is
    // a "portability" driver, and the loader lists it only to a program that
    // says it can cope. Where the loader offers VK_KHR_portability_enumeration
    // we enable it together with the flag that asks for those drivers too.
    std::vector<const char*> enabled_extensions;
    VkInstanceCreateFlags instance_flags = 0;
    if (has_extension(extensions, VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        enabled_extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        instance_flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }
    std::printf("\nportability drivers (MoltenVK): %s\n",
                instance_flags ? "listed too" : "the loader has no such extension");
    // [/portability]

    // [create-instance]
    VkApplicationInfo app{
        .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
        .pApplicationName = "01_instance",
        .applicationVersion = VK_MAKE_API_VERSION(0, 1, 0, 0),
        .pEngineName = "vkt",
        .engineVersion = VK_MAKE_API_VERSION(0, 1, 0, 0),
        .apiVersion = VK_API_VERSION_1_3,  // the highest version this program uses
    };

    MessageCounts counts;
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = on_message,
        .pUserData = &counts,
    };
    // Synchronisation validation checks barriers and semaphores; it is off
    // unless enabled, and from chapter 03 on it is what keeps us honest.
    VkValidationFeatureEnableEXT enabled[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{
        .sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
        .pNext = &messenger_info,  // also report problems inside vkCreateInstance itself
        .enabledValidationFeatureCount = 1,
        .pEnabledValidationFeatures = enabled,
    };

    std::vector<const char*> enabled_layers;
    if (validation) {
        enabled_layers.push_back(validation_layer);
        enabled_extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        enabled_extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }
    VkInstanceCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        .pNext = validation ? &features : nullptr,
        .flags = instance_flags,
        .pApplicationInfo = &app,
        .enabledLayerCount = uint32_t(enabled_layers.size()),
        .ppEnabledLayerNames = enabled_layers.data(),
        .enabledExtensionCount = uint32_t(enabled_extensions.size()),
        .ppEnabledExtensionNames = enabled_extensions.data(),
    };
    VkInstance instance;
    VkResult result = vkCreateInstance(&info, nullptr, &instance);
    // The one failure worth its own words: the loader found no driver at all.
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw vkt::Error(
            "no Vulkan driver found; install one, e.g. apt install mesa-vulkan-drivers");
    VKT_CHECK(result);
    // [/create-instance]

    // [create-messenger]
    // Extension functions are not exported by the loader: we look them up.
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        VKT_CHECK(create(instance, &messenger_info, nullptr, &messenger));
    }
    std::printf("\nvalidation: %s\n", validation ? "on (with synchronisation validation)" : "off");
    // [/create-messenger]

    // [physical-devices]
    VKT_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VKT_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    std::printf("\n%zu physical devices:\n", devices.size());
    for (size_t i = 0; i < devices.size(); ++i) {
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(devices[i], &properties);
        std::printf("  %zu: %s (Vulkan %s)\n", i, properties.deviceName,
                    version_text(properties.apiVersion).c_str());
    }
    // [/physical-devices]

    // [destroy]
    // Children before parents: the messenger belongs to the instance.
    if (messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger, nullptr);
    }
    vkDestroyInstance(instance, nullptr);
    // [/destroy]

    if (devices.empty()) throw vkt::Error("no Vulkan device found: is a Vulkan driver installed?");
    if (validation)
        std::fprintf(stderr, "01_instance: validation: %u warnings, %u errors\n", counts.warnings,
                     counts.errors);
    return counts.warnings + counts.errors > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    return vkt::run_text_chapter(argc, argv, vkt::Flags::instance, run);
}
