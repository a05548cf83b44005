#pragma once
// Dynamic rendering begun in one call: the tidy form of chapter 04's
// vkCmdBeginRendering (one colour target, cleared when rendering begins and
// stored when it ends) with chapter 08's depth attachment (cleared to 1.0, the
// far plane, so every first fragment is nearer; not stored, because nothing
// reads depth after the frame), and chapter 21's resolve of a multisampled
// colour target into a single-sample one. Chapters 04, 08 and 21 write these
// structs out; the chapters after them call this.

#include <vulkan/vulkan.h>

namespace vkt {

// Begins rendering into `colour` (COLOR_ATTACHMENT_OPTIMAL) over the whole
// `extent`, cleared to `clear` (linear RGBA); with a `depth` view also into
// that depth attachment (DEPTH_ATTACHMENT_OPTIMAL). With a `resolve` view
// (chapter 21), `colour` and `depth` are multisampled: when rendering ends,
// the average of each pixel's samples is written to `resolve`
// (COLOR_ATTACHMENT_OPTIMAL, single-sample), and the samples themselves are
// not stored. End with vkCmdEndRendering.
void begin_rendering(VkCommandBuffer cmd, VkImageView colour, VkExtent2D extent,
                     VkClearColorValue clear, VkImageView depth = VK_NULL_HANDLE,
                     VkImageView resolve = VK_NULL_HANDLE);

// Begins rendering into `colour` alone (COLOR_ATTACHMENT_OPTIMAL, no depth)
// without clearing it: `load` LOAD keeps its pixels, to draw over them
// (chapter 21's overlay), DONT_CARE when every pixel will be written anyway
// (chapter 16's full-screen pass). Stored when it ends.
void begin_colour_rendering(VkCommandBuffer cmd, VkImageView colour, VkExtent2D extent,
                            VkAttachmentLoadOp load);

}  // namespace vkt
