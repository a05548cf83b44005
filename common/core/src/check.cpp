#include "vkt/core/check.hpp"

#include <filesystem>

namespace vkt {

const char* result_name(VkResult result) {
    switch (result) {
#define VKT_NAME(r) \
    case r:         \
        return #r;
        VKT_NAME(VK_SUCCESS)
        VKT_NAME(VK_NOT_READY)
        VKT_NAME(VK_TIMEOUT)
        VKT_NAME(VK_EVENT_SET)
        VKT_NAME(VK_EVENT_RESET)
        VKT_NAME(VK_INCOMPLETE)
        VKT_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
        VKT_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        VKT_NAME(VK_ERROR_INITIALIZATION_FAILED)
        VKT_NAME(VK_ERROR_DEVICE_LOST)
        VKT_NAME(VK_ERROR_MEMORY_MAP_FAILED)
        VKT_NAME(VK_ERROR_LAYER_NOT_PRESENT)
        VKT_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
        VKT_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
        VKT_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
        VKT_NAME(VK_ERROR_TOO_MANY_OBJECTS)
        VKT_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
        VKT_NAME(VK_ERROR_FRAGMENTED_POOL)
        VKT_NAME(VK_ERROR_UNKNOWN)
        VKT_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
        VKT_NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        VKT_NAME(VK_ERROR_FRAGMENTATION)
        VKT_NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        VKT_NAME(VK_PIPELINE_COMPILE_REQUIRED)
        VKT_NAME(VK_ERROR_SURFACE_LOST_KHR)
        VKT_NAME(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        VKT_NAME(VK_SUBOPTIMAL_KHR)
        VKT_NAME(VK_ERROR_OUT_OF_DATE_KHR)
        VKT_NAME(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR)
        VKT_NAME(VK_ERROR_VALIDATION_FAILED_EXT)
        VKT_NAME(VK_ERROR_INVALID_SHADER_NV)
#undef VKT_NAME
        default:
            return "VK_RESULT_UNKNOWN";
    }
}

static std::string describe(const char* call, VkResult result, std::source_location where) {
    std::string text = call;
    // Keep the message to one line: the call text up to its argument list.
    if (auto paren = text.find('('); paren != std::string::npos) text = text.substr(0, paren);
    return text + " failed with " + result_name(result) + " (" + std::to_string(result) + ") at " +
           std::filesystem::path(where.file_name()).filename().string() + ":" +
           std::to_string(where.line());
}

VulkanError::VulkanError(const char* call, VkResult result, std::source_location where)
    : Error(describe(call, result, where)), result_(result) {}

}  // namespace vkt
