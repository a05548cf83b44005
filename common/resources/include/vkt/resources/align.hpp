#pragma once
// Rounding a size up to an alignment, taught in chapter 07: each object's
// block in a dynamic uniform buffer starts at a multiple of the device's
// minUniformBufferOffsetAlignment (a power of two, at most 256).

#include <vulkan/vulkan.h>

#include <cassert>

namespace vkt {

// The smallest multiple of `alignment` that is >= size. alignment must be a
// power of two (every Vulkan alignment limit is): then alignment - 1 is a mask
// of the low bits, and clearing them after adding it rounds up.
// align_up(64, 128) == 128, align_up(129, 128) == 256, align_up(0, 128) == 0.
constexpr VkDeviceSize align_up(VkDeviceSize size, VkDeviceSize alignment) {
    assert(alignment != 0 && (alignment & (alignment - 1)) == 0);
    return (size + alignment - 1) & ~(alignment - 1);
}

}  // namespace vkt
