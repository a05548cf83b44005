#pragma once
// Chapter 28's depth pyramid: a mip chain of R32_SFLOAT whose every texel
// holds the farthest depth (the min: depth is reversed) of the 2 x 2 texels
// below it, level 0 made from the depth buffer. The cull pass reads it to
// ask "is everything in this rectangle nearer than my box?" in four reads.

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <algorithm>
#include <bit>
#include <string>
#include <vector>

namespace ch28 {

// [minmax-support]
// The sampler can do the min where the device has samplerFilterMinmax and
// both formats read through it (the depth buffer's and R32_SFLOAT) offer
// SAMPLED_IMAGE_FILTER_MINMAX. Otherwise the shader takes the min itself.
inline bool sampler_min_offered(VkPhysicalDevice physical, bool feature, VkFormat depth_format) {
    if (!feature) return false;
    for (VkFormat format : {depth_format, VK_FORMAT_R32_SFLOAT}) {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(physical, format, &properties);
        if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_MINMAX_BIT))
            return false;
    }
    return true;
}
// [/minmax-support]

class DepthPyramid {
public:
    // depth_view: the depth buffer (DEPTH aspect, SAMPLED usage), of `extent`.
    // readers: the stages that test against it (the cull pass's compute
    // shader, or the task path's task shader) and the fragment stage (the
    // pyramid view).
    DepthPyramid(const vkt::Gpu& gpu, std::string_view chapter, VkImageView depth_view,
                 VkExtent2D extent, bool sampler_min, VkPipelineStageFlags2 readers)
        : device_(gpu.device), depth_extent_(extent), readers_(readers) {
        // [pyramid-image]
        // Level 0 is half the depth buffer, rounded up to a power of two in
        // each direction, so that every level is exactly half the last (as
        // Vulkan sizes mip levels) down to 1 x 1, and texel t of level L
        // covers the pixels [t, t + 1) * 2^(L + 1). Texels past the depth
        // buffer's edge repeat it: a min over more real depths only errs
        // towards "visible".
        const auto power_of_two = [](uint32_t n) { return std::bit_ceil(std::max(n, 1u)); };
        VkExtent2D size{power_of_two((extent.width + 1) / 2),
                        power_of_two((extent.height + 1) / 2)};
        for (VkExtent2D s = size;; s = {std::max(s.width / 2, 1u), std::max(s.height / 2, 1u)}) {
            sizes_.push_back(s);
            if (s.width == 1 && s.height == 1) break;
        }
        const auto levels = uint32_t(sizes_.size());
        image_ = vkt::create_image_2d_mips(
            gpu.physical, gpu.device, VK_FORMAT_R32_SFLOAT, size, levels,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
        // One view per level: the level a pass writes, and the one the next reads.
        for (uint32_t l = 0; l < levels; ++l) {
            const VkImageViewCreateInfo view_info{
                .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                .image = image_.image,
                .viewType = VK_IMAGE_VIEW_TYPE_2D,
                .format = VK_FORMAT_R32_SFLOAT,
                .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, l, 1, 0, 1},
            };
            VkImageView view;
            VKT_CHECK(vkCreateImageView(device_, &view_info, nullptr, &view));
            level_views_.emplace_back(device_, view);
        }
        // [/pyramid-image]

        // [reduction-sampler]
        // Linear filtering between four texels, the four combined by MIN
        // rather than averaged. Clamped to the edge: a texel past the last
        // repeats it. Without the reduction, a nearest sampler for texelFetch.
        const VkSamplerReductionModeCreateInfo reduction{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_REDUCTION_MODE_CREATE_INFO,
            .reductionMode = VK_SAMPLER_REDUCTION_MODE_MIN,
        };
        const VkFilter filter = sampler_min ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
        const VkSamplerCreateInfo sampler_info{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
            .pNext = sampler_min ? &reduction : nullptr,
            .magFilter = filter,
            .minFilter = filter,
            .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
            .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .maxLod = 0.0f,
        };
        VkSampler sampler;
        VKT_CHECK(vkCreateSampler(device_, &sampler_info, nullptr, &sampler));
        sampler_ = vkt::Sampler(device_, sampler);
        // [/reduction-sampler]

        // One descriptor set per level: what it reads (the depth buffer, or
        // the level below) and the level it writes (chapter 13's helpers).
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize pool_sizes[] = {
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, levels},
            {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, levels},
        };
        pool_ = vkt::create_descriptor_pool(device_, levels, pool_sizes);
        for (uint32_t l = 0; l < levels; ++l) {
            const VkDescriptorSet set = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
            vkt::write_image_descriptor(
                device_, set, 0, l == 0 ? depth_view : level_views_[l - 1], sampler_,
                l == 0 ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_GENERAL);
            vkt::write_storage_image_descriptor(device_, set, 1, level_views_[l]);
            sets_.push_back(set);
        }
        const VkDescriptorSetLayout set_layout = set_layout_;
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, 4 * sizeof(int32_t)};
        layout_ = vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&push, 1});
        const VkBool32 use_sampler = sampler_min ? VK_TRUE : VK_FALSE;
        const VkSpecializationMapEntry entry{0, 0, sizeof(VkBool32)};
        const VkSpecializationInfo specialization{1, &entry, sizeof(use_sampler), &use_sampler};
        vkt::ShaderModule shader = vkt::load_shader(device_, chapter, "pyramid.comp");
        pipeline_ = vkt::create_compute_pipeline(device_, shader, layout_, &specialization);

        // The pyramid stays in GENERAL: written as storage, read by texelFetch.
        vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
            vkt::image_barrier(cmd, image_.image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, 1},
                               VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                               VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        });
    }

    // [build]
    // The depth buffer must be in SHADER_READ_ONLY_OPTIMAL, its writes
    // visible to the compute stage. Level by level: each waits for the one
    // below to be written. After the last, the cull pass may read them all.
    void build(VkCommandBuffer cmd) const {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        for (uint32_t l = 0; l < levels(); ++l) {
            if (l > 0)
                vkt::image_barrier(
                    cmd, image_.image, {VK_IMAGE_ASPECT_COLOR_BIT, l - 1, 1, 0, 1},
                    VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
            const VkExtent2D below = l == 0 ? depth_extent_ : sizes_[l - 1];
            const int32_t sizes[4] = {int32_t(below.width), int32_t(below.height),
                                      int32_t(sizes_[l].width), int32_t(sizes_[l].height)};
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(sizes), sizes);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[l],
                                    0, nullptr);
            vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(sizes_[l].width, 8)),
                          uint32_t(vkt::dispatch_count(sizes_[l].height, 8)), 1);
        }
        vkt::image_barrier(cmd, image_.image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels(), 0, 1},
                           VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, readers_,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }
    // [/build]

    // Before the next frame's build overwrites it: the reads of this one done.
    void before_build(VkCommandBuffer cmd) const {
        vkt::image_barrier(cmd, image_.image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels(), 0, 1},
                           VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, readers_,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }

    uint32_t levels() const { return uint32_t(sizes_.size()); }
    VkExtent2D size() const { return sizes_[0]; }
    VkImageView view() const { return image_.view; }  // every level
    VkSampler sampler() const { return sampler_; }

private:
    VkDevice device_;
    std::vector<VkExtent2D> sizes_;  // per level
    VkExtent2D depth_extent_{};
    VkPipelineStageFlags2 readers_;
    vkt::Image image_;
    std::vector<vkt::ImageView> level_views_;
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace ch28
