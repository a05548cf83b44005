// Chapter 02: choosing a physical device and creating a logical device.
//
// A machine may have several Vulkan devices: a discrete GPU, an integrated
// one, a software rasteriser such as lavapipe. We look at each, reject those
// that cannot run the tutorial (and say why), score the rest, and open a
// logical device on the winner with the features we will use: Vulkan 1.3's
// dynamic rendering and synchronization2.

#include "vkt/core/instance.hpp"
#include "vkt/frame/runner.hpp"

// VK_KHR_portability_subset is still a provisional extension: its name is in
// vulkan_beta.h, which vulkan.h includes only with VK_ENABLE_BETA_EXTENSIONS.
#include <vulkan/vulkan_beta.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char* type_name(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return "discrete GPU";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return "integrated GPU";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return "virtual GPU";
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return "CPU (software)";
        default:
            return "other";
    }
}

struct Candidate {
    VkPhysicalDevice device;
    std::string name;
    uint32_t queue_family = 0;
    int score = 0;
    std::string rejected;  // why it cannot be used; empty if it can
};

// [queue-family]
// Queues come in families with different abilities. We want one family that
// can both draw (graphics) and run compute shaders (chapter 13).
bool find_queue_family(VkPhysicalDevice device, uint32_t& family) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        const VkQueueFlags wanted = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & wanted) == wanted) {
            family = i;
            return true;
        }
    }
    return false;
}
// [/queue-family]

// [evaluate]
Candidate evaluate(VkPhysicalDevice device) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    Candidate candidate{device, properties.deviceName};

    // Features are queried through a chain of structs linked by pNext: each
    // Vulkan version (and many extensions) adds one struct of feature flags.
    VkPhysicalDeviceVulkan13Features features13{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
    };
    VkPhysicalDeviceFeatures2 features{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
        .pNext = &features13,
    };
    vkGetPhysicalDeviceFeatures2(device, &features);

    if (properties.apiVersion < VK_API_VERSION_1_3)
        candidate.rejected = "supports only Vulkan " +
                             std::to_string(VK_API_VERSION_MAJOR(properties.apiVersion)) + "." +
                             std::to_string(VK_API_VERSION_MINOR(properties.apiVersion));
    else if (!features13.dynamicRendering)
        candidate.rejected = "has no dynamic rendering";
    else if (!features13.synchronization2)
        candidate.rejected = "has no synchronization2";
    else if (!find_queue_family(device, candidate.queue_family))
        candidate.rejected = "has no queue family for graphics and compute";

    // Prefer real GPUs; among equals, the one with the larger largest image
    // as a rough measure of capability.
    switch (properties.deviceType) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            candidate.score = 4000;
            break;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            candidate.score = 3000;
            break;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            candidate.score = 2000;
            break;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            candidate.score = 1000;
            break;
        default:
            break;
    }
    candidate.score += int(properties.limits.maxImageDimension2D / 1024);

    std::printf("  %-44s %-15s Vulkan %u.%u  ", candidate.name.c_str(),
                type_name(properties.deviceType), VK_API_VERSION_MAJOR(properties.apiVersion),
                VK_API_VERSION_MINOR(properties.apiVersion));
    if (candidate.rejected.empty())
        std::printf("score %d, queue family %u\n", candidate.score, candidate.queue_family);
    else
        std::printf("unsuitable: %s\n", candidate.rejected.c_str());
    return candidate;
}
// [/evaluate]

// [choose]
// --device picks by index or by part of the name; otherwise the best score wins.
const Candidate& choose(const std::vector<Candidate>& candidates, const std::string& selector) {
    if (candidates.empty())
        throw vkt::Error("no Vulkan device found: is a Vulkan driver installed?");
    const Candidate* chosen = nullptr;
    if (!selector.empty()) {
        // All digits: an index (too large to parse is still an index); else a name.
        if (std::all_of(selector.begin(), selector.end(),
                        [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
            size_t index = SIZE_MAX;
            std::from_chars(selector.data(), selector.data() + selector.size(), index);
            if (index >= candidates.size())
                throw vkt::Error("--device " + selector + ": there are only " +
                                 std::to_string(candidates.size()) + " device(s), numbered from 0");
            chosen = &candidates[index];
        } else {
            // Names are matched without regard to case: "h100" finds "NVIDIA H100".
            auto lower = [](std::string text) {
                for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
                return text;
            };
            for (const auto& candidate : candidates)
                if (!chosen && lower(candidate.name).find(lower(selector)) != std::string::npos)
                    chosen = &candidate;
            if (!chosen)
                throw vkt::Error("--device " + selector + ": no device has that in its name");
        }
        if (!chosen->rejected.empty()) throw vkt::Error(chosen->name + " " + chosen->rejected);
        std::printf("\nchose %s: named by --device\n", chosen->name.c_str());
        return *chosen;
    }
    for (const auto& candidate : candidates)
        if (candidate.rejected.empty() && (!chosen || candidate.score > chosen->score))
            chosen = &candidate;
    if (!chosen) throw vkt::Error("no Vulkan device can run this tutorial (see the list above)");
    std::printf("\nchose %s: the highest score\n", chosen->name.c_str());
    return *chosen;
}
// [/choose]

int run(const vkt::Options& options) {
    // Chapter 01's instance, now a helper: validation on, messages counted.
    const bool layer = vkt::instance_layer_available(vkt::validation_layer_name);
    if (options.validation.value_or(false) && !layer)
        throw vkt::Error("--validation: the Khronos validation layer is not installed");
    std::shared_ptr<const vkt::ValidationCounts> counts;
    {
        vkt::Instance instance(
            {.application_name = "02_device", .validation = options.validation.value_or(layer)});
        if (instance.validation()) counts = instance.counts();

        uint32_t count = 0;
        VKT_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
        std::vector<VkPhysicalDevice> devices(count);
        VKT_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
        std::printf("%u physical devices:\n", count);
        std::vector<Candidate> candidates;
        candidates.reserve(devices.size());
        for (VkPhysicalDevice device : devices) candidates.push_back(evaluate(device));
        const Candidate& chosen = choose(candidates, options.device);

        // [portability-subset]
        // A portability driver (MoltenVK) offers VK_KHR_portability_subset, whose
        // features say which parts of Vulkan it lacks. The specification requires
        // us to enable the extension wherever it is offered; the features we ask
        // for here (chapter 02's) are all outside the subset.
        VKT_CHECK(vkEnumerateDeviceExtensionProperties(chosen.device, nullptr, &count, nullptr));
        std::vector<VkExtensionProperties> offered(count);
        VKT_CHECK(
            vkEnumerateDeviceExtensionProperties(chosen.device, nullptr, &count, offered.data()));
        std::vector<const char*> device_extensions;
        for (const auto& extension : offered)
            if (std::strcmp(extension.extensionName, VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME) == 0)
                device_extensions.push_back(VK_KHR_PORTABILITY_SUBSET_EXTENSION_NAME);
        // [/portability-subset]

        // [create-device]
        // One queue from the chosen family. Its priority matters only when
        // several queues of a family compete.
        float priority = 1.0f;
        VkDeviceQueueCreateInfo queue_info{
            .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
            .queueFamilyIndex = chosen.queue_family,
            .queueCount = 1,
            .pQueuePriorities = &priority,
        };
        // The same chain of feature structs, now saying what we switch on.
        VkPhysicalDeviceVulkan13Features features13{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
            .synchronization2 = VK_TRUE,  // simpler, more exact barriers and submits
            .dynamicRendering = VK_TRUE,  // draw without render pass objects
        };
        VkPhysicalDeviceFeatures2 features{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
            .pNext = &features13,
        };
        VkDeviceCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
            .pNext = &features,
            .queueCreateInfoCount = 1,
            .pQueueCreateInfos = &queue_info,
            .enabledExtensionCount = uint32_t(device_extensions.size()),
            .ppEnabledExtensionNames = device_extensions.data(),
        };
        VkDevice device;
        VKT_CHECK(vkCreateDevice(chosen.device, &info, nullptr, &device));

        VkQueue queue;
        vkGetDeviceQueue(device, chosen.queue_family, 0, &queue);
        // [/create-device]
        std::printf("logical device created: queue family %u, queue %p\n", chosen.queue_family,
                    static_cast<void*>(queue));
        std::printf("enabled: Vulkan 1.3 dynamicRendering, synchronization2%s\n",
                    device_extensions.empty() ? "" : "; VK_KHR_portability_subset");

        VKT_CHECK(vkDeviceWaitIdle(device));
        vkDestroyDevice(device, nullptr);
    }  // the instance goes last
    if (!counts) return 0;
    std::fprintf(stderr, "02_device: validation: %u warnings, %u errors\n", counts->warnings.load(),
                 counts->errors.load());
    return counts->warnings + counts->errors > 0 ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    return vkt::run_text_chapter(argc, argv, vkt::Flags::device, run);
}
