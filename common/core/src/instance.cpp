#include "vkt/core/instance.hpp"

#include "vkt/core/portability.hpp"

#include <cstdio>
#include <cstring>

// AddressSanitizer: GCC says so with __SANITIZE_ADDRESS__, Clang with __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define VKT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VKT_ASAN 1
#endif
#endif
#if VKT_ASAN
#include <dlfcn.h>
#endif

namespace vkt {

uint32_t instance_layer_version(const char* name) {
    uint32_t count = 0;
    VKT_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VKT_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    for (const auto& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return layer.specVersion;
    return 0;
}

bool instance_layer_available(const char* name) {
    return instance_layer_version(name) != 0;
}

bool instance_extension_available(const char* name) {
    uint32_t count = 0;
    VKT_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VKT_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data()));
    for (const auto& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* counts = static_cast<ValidationCounts*>(user);
    const bool error = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    (error ? counts->errors : counts->warnings)++;
    std::fprintf(stderr, "[validation %s] %s\n", error ? "error" : "warning", data->pMessage);
    return VK_FALSE;  // never abort the call that triggered the message
}

VkDebugUtilsMessengerCreateInfoEXT messenger_create_info(ValidationCounts* counts) {
    return VkDebugUtilsMessengerCreateInfoEXT{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = on_validation_message,
        .pUserData = counts,
    };
}

Instance::Instance(const InstanceConfig& config) {
    uint32_t loader_version = 0;
    VKT_CHECK(vkEnumerateInstanceVersion(&loader_version));
    if (loader_version < VK_API_VERSION_1_3)
        throw Error("the Vulkan loader supports only " +
                    std::to_string(VK_API_VERSION_MAJOR(loader_version)) + "." +
                    std::to_string(VK_API_VERSION_MINOR(loader_version)) +
                    "; this tutorial needs Vulkan 1.3");

    uint32_t count = 0;
    VKT_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> offered(count);
    VKT_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, offered.data()));
    offered.resize(count);
    // Say plainly which extension is missing (a surface extension without a
    // window system, say) rather than just VK_ERROR_EXTENSION_NOT_PRESENT.
    for (const char* extension : config.extensions)
        if (!offers(offered, extension))
            throw Error(std::string("the Vulkan instance lacks the extension ") + extension);

    // Where the loader offers it, VK_KHR_portability_enumeration and its flag,
    // so that a portability driver such as MoltenVK is listed (chapter 01).
    InstanceExtensions wanted = instance_extensions(offered, config.extensions);
    std::vector<const char*>& extensions = wanted.names;
    std::vector<const char*> layers;
    if (config.validation) {
        // Both extensions are provided by the validation layer itself.
        layers.push_back(validation_layer_name);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }

    VkApplicationInfo app{
        .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
        .pApplicationName = config.application_name.c_str(),
        .applicationVersion = VK_MAKE_API_VERSION(0, 1, 0, 0),
        .pEngineName = "vkt",
        .engineVersion = VK_MAKE_API_VERSION(0, 1, 0, 0),
        .apiVersion = VK_API_VERSION_1_3,
    };

    VkDebugUtilsMessengerCreateInfoEXT messenger_info = messenger_create_info(counts_.get());
    // Synchronisation validation finds missing or wrong barriers; it is off by default.
    VkValidationFeatureEnableEXT enables[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{
        .sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
        .pNext = &messenger_info,
        .enabledValidationFeatureCount = 1,
        .pEnabledValidationFeatures = enables,
    };

#if VKT_ASAN
    // Under AddressSanitizer only (the asan preset): keep the validation layer
    // loaded after vkDestroyInstance unloads it, so that LeakSanitizer, which
    // checks at exit, can name the library of the ~3.7 KB the layer never
    // frees (tests/lsan.supp suppresses exactly that library). Unloaded, its
    // frames are "<unknown module>" and could not be told from ours.
    if (config.validation) dlopen("libVkLayer_khronos_validation.so", RTLD_LAZY | RTLD_NODELETE);
#endif

    VkInstanceCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        .pNext = config.validation ? &features : nullptr,
        .flags = wanted.flags,
        .pApplicationInfo = &app,
        .enabledLayerCount = static_cast<uint32_t>(layers.size()),
        .ppEnabledLayerNames = layers.data(),
        .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
        .ppEnabledExtensionNames = extensions.data(),
    };
    VkResult created = vkCreateInstance(&info, nullptr, &instance_);
    if (created == VK_ERROR_INCOMPATIBLE_DRIVER)  // the loader found no driver at all
        throw Error(
            "no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); "
            "install one, e.g. apt install mesa-vulkan-drivers");
    check(created, "vkCreateInstance");

    if (config.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        VkResult result = create(instance_, &messenger_info, nullptr, &messenger_);
        if (result != VK_SUCCESS) {
            vkDestroyInstance(instance_, nullptr);
            check(result, "vkCreateDebugUtilsMessengerEXT");
        }
    }
}

Instance::~Instance() {
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

}  // namespace vkt
