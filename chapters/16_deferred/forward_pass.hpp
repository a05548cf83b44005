#pragma once
// Chapter 16's forward path, for comparison (--path forward): the same scene
// with the same vertex shader, in one pass that lights each fragment as it is
// drawn (forward.frag). Its depth buffer is chapter 08's.

#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/gbuffer_pass.hpp"

#include <span>

namespace ch16 {

class ForwardPass {
public:
    // One pipeline for the target; with --verify a second one for float
    // targets (verify_format).
    ForwardPass(const vkt::Context& context, const vkt::deferred::SceneMeshes& scene,
                VkFormat verify_format)
        : physical_(context.physical), device_(context.device), scene_(&scene) {
        vkt::ShaderModule scene_vert = vkt::load_shader(device_, context.chapter, "scene.vert");
        vkt::ShaderModule forward_frag = vkt::load_shader(device_, context.chapter, "forward.frag");
        auto forward = [&](VkFormat target) {
            using vkt::deferred::SceneMeshes;
            return vkt::create_graphics_pipeline(device_,
                                                 {.vertex = scene_vert,
                                                  .fragment = forward_frag,
                                                  .layout = scene.layout(),
                                                  .bindings = {&SceneMeshes::vertex_binding, 1},
                                                  .attributes = SceneMeshes::vertex_attributes,
                                                  .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                  .color_formats = {target},
                                                  .depth_format = vkt::deferred::depth_format});
        };
        pipeline_ = forward(context.color_format);
        if (verify_format != VK_FORMAT_UNDEFINED) verify_pipeline_ = forward(verify_format);
    }

    void resize(VkExtent2D extent) {
        depth_ = vkt::create_depth_image(physical_, device_, vkt::deferred::depth_format, extent);
    }

    // One pass, lit as drawn, after chapter 08's barrier that readies depth.
    void record(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent,
                VkImageView target, std::span<const vkt::deferred::Object> objects,
                bool verify = false) const {
        vkt::begin_depth_frame(cmd, depth_.image);
        // Cleared to lighting.frag's background; depth as in chapter 08.
        vkt::begin_rendering(cmd, target, extent, {{0.02f, 0.02f, 0.04f, 1.0f}}, depth_.view);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                          verify ? verify_pipeline_ : pipeline_);
        scene_->draw(cmd, frame_set, objects);
        vkCmdEndRendering(cmd);
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    const vkt::deferred::SceneMeshes* scene_;
    vkt::Pipeline pipeline_, verify_pipeline_;
    vkt::Image depth_;
};

}  // namespace ch16
