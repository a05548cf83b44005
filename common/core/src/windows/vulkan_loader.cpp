// The Windows build's Vulkan loader (cmake/windows.cmake). Debian has no
// vulkan-1.lib for MinGW, so volk opens vulkan-1.dll at run time: every
// vkXxx the chapters call is one of volk's function pointers. They are set
// here, before main: the loader's own functions at start-up, and every
// instance and device function as soon as an instance exists, by wrapping
// vkCreateInstance, so that no chapter needs a line of its own for Windows.
// The Linux build links the Vulkan loader and never compiles this file.
#include <volk.h>

#include <cstdio>
#include <cstdlib>

// Named by the link option -Wl,--undefined, so the linker keeps this file.
extern "C" {
int vkt_vulkan_loader_linked = 0;
}

namespace {

PFN_vkCreateInstance loader_create_instance = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL create_instance_and_load(const VkInstanceCreateInfo* info,
                                                        const VkAllocationCallbacks* allocator,
                                                        VkInstance* instance) {
    const VkResult result = loader_create_instance(info, allocator, instance);
    // Instance and device functions alike, through vkGetInstanceProcAddr:
    // they then work for every device of the instance.
    if (result == VK_SUCCESS) volkLoadInstance(*instance);
    return result;
}

struct LoadVulkan {
    LoadVulkan() {
        if (volkInitialize() != VK_SUCCESS) {
            std::fprintf(stderr,
                         "error: volkInitialize failed: vulkan-1.dll cannot be loaded (no Vulkan "
                         "driver)\n");
            std::exit(1);
        }
        loader_create_instance = vkCreateInstance;
        vkCreateInstance = create_instance_and_load;
    }
};

const LoadVulkan load_vulkan;

}  // namespace
