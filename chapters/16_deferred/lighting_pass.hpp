#pragma once
// Chapter 16's pass 2, the lighting pass: one full-screen triangle that reads
// the G-buffer (set 1) and the lights (set 0) and lights every pixel, or shows
// one G-buffer target alone (--view). Set 1 is this pass's own: one set for
// all frames in flight, like the G-buffer it points at.

#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/gbuffer_pass.hpp"

namespace ch16 {

class LightingPass {
public:
    // One pipeline for the target; with --verify a second one for float
    // targets (verify_format).
    LightingPass(const vkt::Context& context, VkDescriptorSetLayout frame_layout,
                 VkFormat verify_format)
        : device_(context.device) {
        // The G-buffer layout and pool are chapter 07's helpers; the bindings
        // and writes are vkt::deferred::GBufferPass's (taught on this page).
        const auto bindings = vkt::deferred::GBufferPass::bindings(VK_SHADER_STAGE_FRAGMENT_BIT);
        gbuffer_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
        pool_ = vkt::create_descriptor_pool(device_, 1, {&size, 1});
        gbuffer_set_ = vkt::allocate_descriptor_set(device_, pool_, gbuffer_layout_);

        const VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                        sizeof(vkt::deferred::LightingPush)};
        const VkDescriptorSetLayout sets[] = {frame_layout, gbuffer_layout_};
        layout_ = vkt::create_pipeline_layout(device_, sets, {&range, 1});
        vkt::ShaderModule fullscreen =
            vkt::load_shader(device_, context.chapter, "fullscreen.vert");
        vkt::ShaderModule lighting_frag =
            vkt::load_shader(device_, context.chapter, "lighting.frag");
        // [pipelines]
        // The lighting pass: no vertex input, no depth, one colour target.
        auto lighting = [&](VkFormat target) {
            return vkt::create_graphics_pipeline(device_, {.vertex = fullscreen,
                                                           .fragment = lighting_frag,
                                                           .layout = layout_,
                                                           .color_formats = {target}});
        };
        // [/pipelines]
        pipeline_ = lighting(context.color_format);
        if (verify_format != VK_FORMAT_UNDEFINED) verify_pipeline_ = lighting(verify_format);
    }

    // Set 1 points at the G-buffer's images: after each GBufferPass::resize.
    void resize(const vkt::deferred::GBufferPass& gbuffer) const {
        gbuffer.write_descriptors(gbuffer_set_);
    }

    // [lighting-pass]
    // Pass 2: one full-screen triangle into the target; no vertex buffer, no
    // depth. Set 0 holds the lights, set 1 the G-buffer.
    void draw(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent, VkImageView target,
              const vkt::deferred::LightingPush& push, bool verify = false) const {
        vkt::deferred::begin_full_screen(cmd, target, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                          verify ? verify_pipeline_ : pipeline_);
        const VkDescriptorSet sets[] = {frame_set, gbuffer_set_};
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 2, sets, 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    // [/lighting-pass]

private:
    VkDevice device_;
    vkt::DescriptorSetLayout gbuffer_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet gbuffer_set_ = VK_NULL_HANDLE;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_, verify_pipeline_;
};

}  // namespace ch16
