#pragma once
// Errors. Taught in chapter 01: every Vulkan call returns a VkResult, and a
// failure is only useful when it says which call failed, with what, and where.

#include <vulkan/vulkan.h>

#include <source_location>
#include <stdexcept>
#include <string>

namespace vkt {

// The symbolic name of a VkResult, e.g. "VK_ERROR_OUT_OF_DATE_KHR".
const char* result_name(VkResult result);

// [vulkan-error]
// Anything that stops a chapter: a missing file, no suitable device, a
// Vulkan call that failed... `catch (const vkt::Error&)` catches them all.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A Vulkan call returned an error. what() names the call (without its
// arguments), the result by name and number, and the source file and line:
// "vkCreateDevice failed with VK_ERROR_FEATURE_NOT_PRESENT (-8) at device.cpp:<line>".
// result() lets a caller act on one result (out of memory, say).
class VulkanError : public Error {
public:
    VulkanError(const char* call, VkResult result, std::source_location where);
    VkResult result() const { return result_; }

private:
    VkResult result_;
};

// Throws VulkanError for an error code (all are negative). Success codes,
// including VK_SUBOPTIMAL_KHR and VK_INCOMPLETE, are returned to the caller.
inline VkResult check(VkResult result, const char* call,
                      std::source_location where = std::source_location::current()) {
    if (result < 0) throw VulkanError(call, result, where);
    return result;
}

}  // namespace vkt

// VKT_CHECK(vkCreateFoo(...)) records the text of the call for the message.
#define VKT_CHECK(call) ::vkt::check((call), #call)
// [/vulkan-error]
