#pragma once
// Chapter 21: which sample counts a device can render a colour and depth
// target with, and the reader's --samples checked against them. Pure
// functions of the limits, so tests/unit/test_multisample.cpp can feed them
// any device's numbers.

#include "vkt/core/check.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>

// [offered]
// A count is usable only if the colour and the depth attachment both allow
// it: the two limits are separate masks (VK_SAMPLE_COUNT_4_BIT is 4, and so
// on), and a device may offer more samples for colour than for depth.
inline VkSampleCountFlags offered_sample_counts(const VkPhysicalDeviceLimits& limits) {
    return limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts;
}
// [/offered]

// "1, 4" for a mask of VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT.
inline std::string sample_count_list(VkSampleCountFlags counts) {
    std::string list;
    for (uint32_t count = 1; count <= 64; count *= 2)
        if (counts & count) list += (list.empty() ? "" : ", ") + std::to_string(count);
    return list.empty() ? "none" : list;
}

// The flag bit for `requested` samples, or an error naming the device and
// what it offers (exit status 1: the command line was fine, the device is not).
inline VkSampleCountFlagBits checked_sample_count(uint32_t requested, VkSampleCountFlags offered,
                                                  std::string_view device) {
    const bool power_of_two = requested != 0 && (requested & (requested - 1)) == 0;
    if (!power_of_two || requested > 64 || !(offered & requested))
        throw vkt::Error("--samples " + std::to_string(requested) + ": " + std::string(device) +
                         " cannot render a colour and depth target with " +
                         std::to_string(requested) + " samples per pixel (it offers " +
                         sample_count_list(offered) + ")");
    return VkSampleCountFlagBits(requested);
}
