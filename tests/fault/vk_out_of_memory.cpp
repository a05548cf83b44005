// A fault for the troubleshooting table's "device out of memory" row: this
// library, preloaded into a chapter (LD_PRELOAD), makes vkAllocateMemory
// fail with VK_ERROR_OUT_OF_DEVICE_MEMORY from the Nth call on
// (VKT_FAIL_ALLOCATION=N, default 1), as a GPU with too little memory would.
// No chapter or common/ code knows about it; the test checks the message a
// reader then sees.
#include <vulkan/vulkan.h>

#include <dlfcn.h>

#include <cstdlib>

extern "C" VKAPI_ATTR VkResult VKAPI_CALL vkAllocateMemory(VkDevice device,
                                                           const VkMemoryAllocateInfo* info,
                                                           const VkAllocationCallbacks* alloc,
                                                           VkDeviceMemory* memory) {
    static const auto real =
        reinterpret_cast<PFN_vkAllocateMemory>(dlsym(RTLD_NEXT, "vkAllocateMemory"));
    static const long fail_from = [] {
        const char* text = std::getenv("VKT_FAIL_ALLOCATION");
        return text ? std::atol(text) : 1L;
    }();
    static long calls = 0;
    if (++calls >= fail_from) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    return real(device, info, alloc, memory);
}
