#pragma once
// The depth buffer of chapter 08: choosing a depth format the device can
// render to, creating the image, and the barrier that readies it each frame.
// Chapter 21 makes it multisampled and transient.

#include "vkt/core/memory.hpp"

#include <span>

namespace vkt {

// The formats choose_depth_format tries, best first: D32_SFLOAT (most
// precision, no stencil we do not use), D32_SFLOAT_S8_UINT, D24_UNORM_S8_UINT,
// D16_UNORM (the one format every device must support as a depth attachment).
std::span<const VkFormat> depth_format_candidates();

// The first candidate with DEPTH_STENCIL_ATTACHMENT in its optimalTilingFeatures
// (vkGetPhysicalDeviceFormatProperties). Throws Error naming the formats tried
// when none has it.
VkFormat choose_depth_format(VkPhysicalDevice physical);

// "VK_FORMAT_D32_SFLOAT" and so on for the candidates; "another format" else.
const char* depth_format_name(VkFormat format);

// Whether the format has a stencil aspect besides depth.
bool has_stencil(VkFormat format);

// A depth attachment of the colour target's size: usage DEPTH_STENCIL_ATTACHMENT,
// device-local, its view with the DEPTH aspect. Recreate it when the target is
// resized (Renderer::resize). Chapter 21: with `samples` per pixel, and
// `transient` (TRANSIENT_ATTACHMENT, lazily allocated memory where the device
// has it: see create_attachment_image), for depth that is never stored.
Image create_depth_image(VkPhysicalDevice physical, VkDevice device, VkFormat format,
                         VkExtent2D extent, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT,
                         bool transient = false);

// The barrier at the start of each frame that draws with depth: the previous
// contents are thrown away (old layout UNDEFINED; the frame clears depth), the
// image goes to DEPTH_ATTACHMENT_OPTIMAL, and the layout change waits for the
// previous frame's depth writes (EARLY|LATE_FRAGMENT_TESTS) to finish, so one
// depth image can serve every frame in flight. Needs the Vulkan 1.2 feature
// separateDepthStencilLayouts (chapter 08 requires it).
void begin_depth_frame(VkCommandBuffer cmd, VkImage depth_image);

}  // namespace vkt
