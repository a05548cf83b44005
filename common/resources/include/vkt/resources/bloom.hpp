#pragma once
// Chapter 23's bloom (--bloom): bright light bleeds into its surroundings, as
// it does in an eye or a lens. The HDR image is halved again and again into
// the mip levels of one image by a compute pass (each level a wider blur),
// and the levels are added back up from the smallest; the tone-mapping pass
// mixes level 0, divided by the number of levels, into the picture. Chapter
// 29 records it on a queue of its own (a compute-only family), which is why
// record() is told which stages outside the chain read it on the same queue,
// and widens the tent of the way up (`radius`, 1 in chapter 23) to give that
// queue more work. `karis` (chapter 23's --bloom-average karis) weighs the
// first halving's taps by 1 / (1 + luma), Karis's average, against fireflies.
// Its shaders are shaders/common/bloom/ (SHARED_SHADERS bloom/bloom_down.comp
// bloom/bloom_up.comp). record()'s `halfway`, called between the way down and
// the way up, is where chapter 23's --view bloom copies the way down out.

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"
#include "vkt/resources/upload.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace vkt {

class Bloom {
public:
    static constexpr uint32_t max_levels = 6;

    Bloom(const vkt::Gpu& gpu, const std::string& chapter, uint32_t radius = 1, bool karis = false)
        : gpu_(gpu), radius_(int32_t(radius)) {
        // [bloom-sampler]
        // Linear filtering, and clamped at the edges: a repeating sampler
        // would blur the left edge's light into the right edge.
        const VkSamplerCreateInfo sampler_info{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
            .magFilter = VK_FILTER_LINEAR,
            .minFilter = VK_FILTER_LINEAR,
            .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
            .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        };
        // [/bloom-sampler]
        VkSampler sampler;
        VKT_CHECK(vkCreateSampler(gpu_.device, &sampler_info, nullptr, &sampler));
        sampler_ = vkt::Sampler(gpu_.device, sampler);
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(gpu_.device, bindings);
        const VkDescriptorSetLayout layouts[] = {set_layout_};
        const VkPushConstantRange tent{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof radius_};
        layout_ = vkt::create_pipeline_layout(gpu_.device, layouts, {&tent, 1});
        const vkt::ShaderModule down = vkt::load_shader(gpu_.device, chapter, "bloom_down.comp");
        const vkt::ShaderModule up = vkt::load_shader(gpu_.device, chapter, "bloom_up.comp");
        down_ = vkt::create_compute_pipeline(gpu_.device, down, layout_);
        up_ = vkt::create_compute_pipeline(gpu_.device, up, layout_);
        // [bloom-karis-pipeline]
        // The first halving, from the HDR image, with bloom_down.comp's
        // constant `karis` on; every later one keeps the plain mean.
        if (karis) {
            const VkBool32 on = VK_TRUE;
            const VkSpecializationMapEntry entry{0, 0, sizeof on};
            const VkSpecializationInfo specialization{1, &entry, sizeof on, &on};
            first_down_ = vkt::create_compute_pipeline(gpu_.device, down, layout_, &specialization);
        }
        // [/bloom-karis-pipeline]
    }

    // The chain for an HDR image of `extent`, read through `hdr_view`
    // (SHADER_READ_ONLY_OPTIMAL when record() runs); the GPU is idle.
    void resize(VkExtent2D extent, VkImageView hdr_view) {
        sets_.clear();
        views_.clear();  // before the image they view
        extent_ = {std::max(extent.width / 2, 1u), std::max(extent.height / 2, 1u)};
        levels_ = std::min(max_levels, vkt::mip_level_count(extent_.width, extent_.height));
        image_ = vkt::create_image_2d_mips(
            gpu_.physical, gpu_.device, VK_FORMAT_R16G16B16A16_SFLOAT, extent_, levels_,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
            VK_IMAGE_ASPECT_COLOR_BIT);
        for (uint32_t level = 0; level < levels_; ++level) {
            const VkImageViewCreateInfo info{
                .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                .image = image_.image,
                .viewType = VK_IMAGE_VIEW_TYPE_2D,
                .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, 1},
            };
            VkImageView view;
            VKT_CHECK(vkCreateImageView(gpu_.device, &info, nullptr, &view));
            views_.emplace_back(gpu_.device, view);
        }
        // One set per step: down into level 0 (from the HDR image) .. levels - 1,
        // then up into levels - 2 .. 0.
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * levels_},
            {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 2 * levels_}};
        pool_ = vkt::create_descriptor_pool(gpu_.device, 2 * levels_, sizes);
        for (uint32_t step = 0; step + 1 < 2 * levels_; ++step) {
            const bool down = step < levels_;
            const uint32_t target = down ? step : 2 * levels_ - 2 - step;
            const VkImageView source =
                down ? (step == 0 ? hdr_view : VkImageView(views_[step - 1])) : views_[target + 1];
            const VkDescriptorSet set =
                vkt::allocate_descriptor_set(gpu_.device, pool_, set_layout_);
            vkt::write_image_descriptor(gpu_.device, set, 0, source, sampler_,
                                        down && step == 0 ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL
                                                          : VK_IMAGE_LAYOUT_GENERAL);
            vkt::write_storage_image_descriptor(gpu_.device, set, 1, views_[target]);
            sets_.push_back(set);
        }
        // The tone-mapping pass may read level 0 before any bloom is drawn
        // (--bloom 0): it must be in GENERAL, and hold zeros. The fence wait
        // after this submit orders nothing on the GPU, so a barrier makes the
        // zeros visible to those reads and orders the clear before record()'s
        // barrier, whose source stages are the fragment and compute shaders.
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            vkt::image_barrier(cmd, image_.image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels_, 0, 1},
                               VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                               VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                               VK_ACCESS_2_TRANSFER_WRITE_BIT);
            const VkClearColorValue zero{};
            const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, levels_, 0, 1};
            vkCmdClearColorImage(cmd, image_.image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &all);
            vkt::memory_barrier(
                cmd, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        });
    }

    // [bloom-record]
    // Last frame's chain is thrown away (after its reads, by this chain and
    // the tone-mapping pass: `readers`, the stages that read level 0 on this
    // queue, chapter 23's fragment shader). Then down the chain, then up,
    // each dispatch reading what the one before it wrote: a barrier between
    // every two. The HDR image must already be readable by compute shaders.
    // `halfway`, if given, is recorded between the way down and the way up.
    void record(VkCommandBuffer cmd, VkPipelineStageFlags2 readers,
                const std::function<void(VkCommandBuffer)>& halfway = {}) const {
        vkt::image_barrier(cmd, image_.image, {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels_, 0, 1},
                           VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                           readers | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof radius_, &radius_);
        for (uint32_t step = 0; step + 1 < 2 * levels_; ++step) {
            const bool down = step < levels_;
            const uint32_t target = down ? step : 2 * levels_ - 2 - step;
            const VkExtent2D size = vkt::mip_extent(extent_.width, extent_.height, target);
            const bool karis = step == 0 && first_down_;
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                              karis ? first_down_ : (down ? down_ : up_));
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1,
                                    &sets_[step], 0, nullptr);
            vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(size.width, 8)),
                          uint32_t(vkt::dispatch_count(size.height, 8)), 1);
            // Storage writes to the next dispatch's reads (and, after the
            // last, the tone-mapping pass's).
            vkt::memory_barrier(
                cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | readers,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            if (step + 1 == levels_ && halfway) halfway(cmd);
        }
    }
    // [/bloom-record]

    VkImageView level0() const { return views_.front(); }
    VkImage image() const { return image_.image; }
    VkImageView view() const { return image_.view; }  // every level
    VkExtent2D extent() const { return extent_; }     // level 0's: half the HDR image's
    uint32_t levels() const { return levels_; }
    VkSampler sampler() const { return sampler_; }

private:
    vkt::Gpu gpu_;
    int32_t radius_;  // the tent's, read by bloom_up.comp
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline down_, up_;
    vkt::Pipeline first_down_;  // only with karis: the first halving's
    VkExtent2D extent_{};
    uint32_t levels_ = 0;
    vkt::Image image_;
    std::vector<vkt::ImageView> views_;  // after the image: destroyed first
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;
};

}  // namespace vkt
