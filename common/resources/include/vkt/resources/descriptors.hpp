#pragma once
// Descriptor set layouts, pools and sets: the tidy form of chapter 07, which
// writes each of these out with the C API. A layout says what a set holds
// (binding number, type, count, stages), a pool hands out sets, and a write
// points one binding of a set at a buffer or an image.

#include "vkt/core/owned.hpp"

#include <span>

namespace vkt {

// vkCreateDescriptorSetLayout with these bindings and no flags.
DescriptorSetLayout create_descriptor_set_layout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings);

// vkCreateDescriptorPool for at most max_sets sets, holding in all at most
// the descriptors `sizes` names (per type). No flags: sets are freed with the
// pool, never one by one.
DescriptorPool create_descriptor_pool(VkDevice device, uint32_t max_sets,
                                      std::span<const VkDescriptorPoolSize> sizes);

// One set of `layout` from `pool` (vkAllocateDescriptorSets). The pool owns it:
// it is freed when the pool is destroyed.
VkDescriptorSet allocate_descriptor_set(VkDevice device, VkDescriptorPool pool,
                                        VkDescriptorSetLayout layout);

// Points `binding` of `set` at buffer[offset, offset + range) (range may be
// VK_WHOLE_SIZE). type: UNIFORM_BUFFER, UNIFORM_BUFFER_DYNAMIC, STORAGE_BUFFER
// or STORAGE_BUFFER_DYNAMIC; for a dynamic one, range is the size one draw
// sees and the offset given to vkCmdBindDescriptorSets is added to `offset`.
void write_buffer_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                             VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset,
                             VkDeviceSize range);

// Points `binding` of `set` (a COMBINED_IMAGE_SAMPLER) at view + sampler; the
// image will be in `layout` when the shader reads it (chapter 09).
void write_image_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                            VkImageView view, VkSampler sampler, VkImageLayout layout);

// Points `binding` of `set` (a STORAGE_IMAGE) at view, which a compute shader
// writes in the GENERAL layout (chapter 17's shaded image, chapter 20's
// target).
void write_storage_image_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                                    VkImageView view);

}  // namespace vkt
