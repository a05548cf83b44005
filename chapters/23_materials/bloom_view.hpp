#pragma once
// Chapter 23's view of the bloom's chain (--view bloom, page 23d): every
// level of this frame's chain, as the way down left it and as the way up
// left it, drawn into the HDR image in place of the scene once the bloom has
// read the scene, so that the same exposure and tone curve show it. The way
// up adds to the levels in place, so the way down is copied out halfway
// (vkt::Bloom::record's `halfway`) into an image of the same shape.

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/resources/bloom.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

class BloomView {
public:
    BloomView(const vkt::Gpu& gpu, const std::string& chapter, const vkt::Bloom& bloom,
              VkShaderModule fullscreen, VkFormat colour)
        : gpu_(gpu), bloom_(bloom) {
        sampler_ = vkt::create_sampler(gpu.device, 0.0f);  // read by texelFetch only
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
            {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr}};
        set_layout_ = vkt::create_descriptor_set_layout(gpu.device, bindings);
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}};
        pool_ = vkt::create_descriptor_pool(gpu.device, 1, sizes);
        set_ = vkt::allocate_descriptor_set(gpu.device, pool_, set_layout_);
        const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(glm::uvec4)};
        const VkDescriptorSetLayout layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(gpu.device, layouts, {&push, 1});
        const vkt::ShaderModule fragment = vkt::load_shader(gpu.device, chapter, "bloom_view.frag");
        pipeline_ = vkt::create_graphics_pipeline(gpu.device, {.vertex = fullscreen,
                                                               .fragment = fragment,
                                                               .layout = layout_,
                                                               .color_formats = {colour}});
    }

    // After the chain's own resize (the GPU idle): the copy takes its shape.
    void resize() {
        levels_ = bloom_.levels();
        down_ = vkt::create_image_2d_mips(
            gpu_.physical, gpu_.device, VK_FORMAT_R16G16B16A16_SFLOAT, bloom_.extent(), levels_,
            VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
            VK_IMAGE_ASPECT_COLOR_BIT);
        vkt::write_image_descriptor(gpu_.device, set_, 0, down_.view, sampler_,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        vkt::write_image_descriptor(gpu_.device, set_, 1, bloom_.view(), sampler_,
                                    VK_IMAGE_LAYOUT_GENERAL);
    }

    // Halfway through the chain: its levels, just written by the way down's
    // compute shaders, are copied out before the way up writes them again.
    // For the copy the chain leaves GENERAL for the layout a copy reads best;
    // the copy's own image is thrown away first, after last frame's view read it.
    void keep_down(VkCommandBuffer cmd) const {
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, levels_, 0, 1};
        vkt::image_barrier(
            cmd, bloom_.image(), all, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::image_barrier(cmd, down_.image, all, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT);
        std::vector<VkImageCopy> regions;
        for (uint32_t level = 0; level < levels_; ++level) {
            const VkExtent2D size =
                vkt::mip_extent(bloom_.extent().width, bloom_.extent().height, level);
            const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
            regions.push_back({layers, {0, 0, 0}, layers, {0, 0, 0}, {size.width, size.height, 1}});
        }
        vkCmdCopyImage(cmd, bloom_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, down_.image,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()),
                       regions.data());
        // The way up reads and writes the chain once the copy has read it;
        // the view's fragment shader reads the copy.
        vkt::image_barrier(
            cmd, bloom_.image(), all, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
            VK_PIPELINE_STAGE_2_COPY_BIT, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkt::image_barrier(cmd, down_.image, all, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }

    // What vkt::Bloom::record calls halfway.
    std::function<void(VkCommandBuffer)> halfway() const {
        return [this](VkCommandBuffer cmd) { keep_down(cmd); };
    }

    // After the bloom (which read the scene from the HDR image, and whose last
    // barrier makes the chain readable by fragment shaders): the panels are
    // drawn over the scene, and the tone-mapping pass reads them instead.
    void draw(VkCommandBuffer cmd, const vkt::Image& hdr, VkExtent2D extent) const {
        vkt::image_barrier(cmd, hdr.image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        vkt::begin_colour_rendering(cmd, hdr.view, extent, VK_ATTACHMENT_LOAD_OP_DONT_CARE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);
        const glm::uvec4 push{extent.width, extent.height, levels_, 0};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
        vkt::image_barrier(
            cmd, hdr.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }

private:
    vkt::Gpu gpu_;
    const vkt::Bloom& bloom_;  // the chapter's, which outlives this view
    uint32_t levels_ = 0;
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
    vkt::Image down_;  // the way down's levels, copied
};
