#include "vkt/resources/descriptors.hpp"

#include "vkt/core/check.hpp"

namespace vkt {

DescriptorSetLayout create_descriptor_set_layout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings) {
    VkDescriptorSetLayoutCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
        .bindingCount = static_cast<uint32_t>(bindings.size()),
        .pBindings = bindings.data(),
    };
    VkDescriptorSetLayout layout;
    VKT_CHECK(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout));
    return DescriptorSetLayout(device, layout);
}

DescriptorPool create_descriptor_pool(VkDevice device, uint32_t max_sets,
                                      std::span<const VkDescriptorPoolSize> sizes) {
    VkDescriptorPoolCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
        .maxSets = max_sets,
        .poolSizeCount = static_cast<uint32_t>(sizes.size()),
        .pPoolSizes = sizes.data(),
    };
    VkDescriptorPool pool;
    VKT_CHECK(vkCreateDescriptorPool(device, &info, nullptr, &pool));
    return DescriptorPool(device, pool);
}

VkDescriptorSet allocate_descriptor_set(VkDevice device, VkDescriptorPool pool,
                                        VkDescriptorSetLayout layout) {
    VkDescriptorSetAllocateInfo info{
        .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
        .descriptorPool = pool,
        .descriptorSetCount = 1,
        .pSetLayouts = &layout,
    };
    VkDescriptorSet set;
    VKT_CHECK(vkAllocateDescriptorSets(device, &info, &set));
    return set;
}

namespace {

// The three writes below differ only in what they point at: one descriptor of
// one binding, element 0 (chapter 07 writes the same struct out in full).
void write_one(VkDevice device, VkDescriptorSet set, uint32_t binding, VkDescriptorType type,
               const VkDescriptorBufferInfo* buffer_info, const VkDescriptorImageInfo* image_info) {
    VkWriteDescriptorSet write{
        .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
        .dstSet = set,
        .dstBinding = binding,
        .dstArrayElement = 0,
        .descriptorCount = 1,
        .descriptorType = type,
        .pImageInfo = image_info,
        .pBufferInfo = buffer_info,
    };
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
}

}  // namespace

void write_buffer_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                             VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset,
                             VkDeviceSize range) {
    VkDescriptorBufferInfo buffer_info{.buffer = buffer, .offset = offset, .range = range};
    write_one(device, set, binding, type, &buffer_info, nullptr);
}

void write_image_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                            VkImageView view, VkSampler sampler, VkImageLayout layout) {
    VkDescriptorImageInfo image_info{.sampler = sampler, .imageView = view, .imageLayout = layout};
    write_one(device, set, binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, nullptr,
              &image_info);
}

void write_storage_image_descriptor(VkDevice device, VkDescriptorSet set, uint32_t binding,
                                    VkImageView view) {
    VkDescriptorImageInfo image_info{.imageView = view, .imageLayout = VK_IMAGE_LAYOUT_GENERAL};
    write_one(device, set, binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, nullptr, &image_info);
}

}  // namespace vkt
