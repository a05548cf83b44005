#pragma once
// Chapter 23's views of the image-based light (--view sky, irradiance,
// prefiltered, brdf): the images environment.hpp makes before the first
// frame, drawn into the HDR image in place of the scene, so that the same
// exposure and tone curve show them as the scene would. The two cubes are
// unfolded into a cross of six faces; the prefiltered cube's levels are six
// panoramas, one per roughness step; the BRDF table is a square, its two
// numbers red and green.

#include "environment.hpp"

#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"

#include <glm/glm.hpp>

#include <string>

class IblView {
public:
    enum Kind : uint32_t { sky = 1, irradiance, prefiltered, brdf };

    static Kind kind(const std::string& view) {
        return view == "sky"           ? sky
               : view == "irradiance"  ? irradiance
               : view == "prefiltered" ? prefiltered
                                       : brdf;
    }

    IblView(const vkt::Gpu& gpu, const std::string& chapter, const Environment& environment,
            Kind kind, VkShaderModule fullscreen, VkFormat colour, VkFormat depth)
        : kind_(kind), set_(environment.set()) {
        const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(glm::uvec4)};
        const VkDescriptorSetLayout layouts[] = {environment.layout()};
        layout_ = vkt::create_pipeline_layout(gpu.device, layouts, {&push, 1});
        const vkt::ShaderModule fragment = vkt::load_shader(gpu.device, chapter, "ibl_view.frag");
        // Inside the scene pass's rendering, which has a depth attachment:
        // the view neither tests nor writes it.
        pipeline_ =
            vkt::create_graphics_pipeline(gpu.device, {.vertex = fullscreen,
                                                       .fragment = fragment,
                                                       .layout = layout_,
                                                       .color_formats = {colour},
                                                       .depth_format = depth,
                                                       .depth_write = false,
                                                       .depth_compare = VK_COMPARE_OP_ALWAYS});
    }

    void draw(VkCommandBuffer cmd, VkExtent2D extent) const {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);
        const glm::uvec4 push{extent.width, extent.height, kind_, Environment::specular_levels};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }

private:
    Kind kind_;
    VkDescriptorSet set_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};
