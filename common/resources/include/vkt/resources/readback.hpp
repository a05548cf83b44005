#pragma once
// Reading a frame back to the CPU, for --screenshot, taught in chapter 03. The
// copy is recorded into the frame's own command buffer, right after the image
// reaches its final state, so the screenshot is exactly what that frame
// presented.

#include "vkt/core/memory.hpp"
#include "vkt/resources/image_io.hpp"

namespace vkt {

struct Readback {
    Buffer buffer;  // host-visible, host-coherent, mapped
    VkExtent2D extent{};
    VkFormat format = VK_FORMAT_UNDEFINED;
};

// Records: copy `image` (in TRANSFER_SRC_OPTIMAL, after a barrier that made its
// last write visible to the COPY stage) into the readback buffer, then make the
// copy visible to the host. Grows the buffer when needed, so the caller must
// know the GPU is done with it (the frame slot's fence).
void record_readback(VkPhysicalDevice physical, VkDevice device, VkCommandBuffer cmd, VkImage image,
                     VkFormat format, VkExtent2D extent, Readback& readback);

// Tightly packed 8-bit RGBA or BGRA pixels as RGBA, alpha set to 255 (the
// screen shows no alpha, so neither does a screenshot). Throws Error for
// any other format.
RgbaImage to_rgba(const void* pixels, VkExtent2D extent, VkFormat format);

}  // namespace vkt
