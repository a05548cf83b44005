#pragma once
// Dynamic rendering begun in one call: the tidy form of chapter 04's
// vkCmdBeginRendering (one colour target, cleared when rendering begins and
// stored when it ends) with chapter 08's depth attachment (cleared to 1.0, the
// far plane, so every first fragment is nearer; not stored, because nothing
// reads depth after the frame). Chapters 04 and 08 write these structs out;
// the chapters after them call this.

#include <vulkan/vulkan.h>

namespace vkt {

// Begins rendering into `colour` (COLOR_ATTACHMENT_OPTIMAL) over the whole
// `extent`, cleared to `clear` (linear RGBA); with a `depth` view also into
// that depth attachment (DEPTH_ATTACHMENT_OPTIMAL). End with vkCmdEndRendering.
void begin_rendering(VkCommandBuffer cmd, VkImageView colour, VkExtent2D extent,
                     VkClearColorValue clear, VkImageView depth = VK_NULL_HANDLE);

}  // namespace vkt
