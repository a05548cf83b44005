#pragma once
// Chapter 22's --view map: the shadow map itself, drawn in place of the lit
// scene. Each cascade's layer is a square, side by side from the nearest
// cascade to the farthest, framed in the colour --view cascades gives it. A
// texel's depth is how far the light reaches there: dark near the light, pale
// far from it. Each cascade's box reaches `behind` metres further towards the
// light than its slice of the view needs (cascades.hpp), so every caster's
// depth lies in the last part of [0, 1]; that part, from the slice's nearest
// possible depth to 1, is stretched over black to white. Where nothing was
// drawn the map keeps its clear value 1.0, drawn pale blue. The map is read through a
// plain sampler (the lit pass's comparison sampler answers only "nearer or
// not").

#include "vkt/core/check.hpp"
#include "vkt/core/owned.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_access.hpp>

#include <string>

class MapView {
public:
    MapView() = default;
    MapView(VkDevice device, const std::string& chapter, VkFormat color_format,
            VkImageView shadow_layers, uint32_t cascades)
        : cascades_(cascades) {
        const VkSamplerCreateInfo sampler_info{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
            .magFilter = VK_FILTER_NEAREST,
            .minFilter = VK_FILTER_NEAREST,
            .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
            .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        };
        VkSampler sampler;
        VKT_CHECK(vkCreateSampler(device, &sampler_info, nullptr, &sampler));
        sampler_ = vkt::Sampler(device, sampler);
        const VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                                   VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
        set_layout_ = vkt::create_descriptor_set_layout(device, {&binding, 1});
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
        pool_ = vkt::create_descriptor_pool(device, 1, {&size, 1});
        set_ = vkt::allocate_descriptor_set(device, pool_, set_layout_);
        vkt::write_image_descriptor(device, set_, 0, shadow_layers, sampler_,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        const VkPushConstantRange push{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
        const VkDescriptorSetLayout layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device, layouts, {&push, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device, chapter, "fullscreen.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device, chapter, "map_view.frag");
        pipeline_ = vkt::create_graphics_pipeline(device, {.vertex = vertex,
                                                           .fragment = fragment,
                                                           .layout = layout_,
                                                           .color_formats = {color_format}});
    }

    // [near-depth]
    // The depth at which a cascade's slice begins: its box is 2 * half +
    // behind deep and the slice's sphere (radius half) fills the far 2 * half
    // of it. The matrix's first row has length 1 / half, its third 1 / depth.
    static float slice_near_depth(const glm::mat4& light_from_world) {
        const float half = 1.0f / glm::length(glm::vec3(glm::row(light_from_world, 0)));
        const float depth = 1.0f / glm::length(glm::vec3(glm::row(light_from_world, 2)));
        return 1.0f - 2.0f * half / depth;
    }
    // [/near-depth]

    // After the shadow pass's barrier (the map is SHADER_READ_ONLY_OPTIMAL and
    // visible to fragment shaders): one triangle over the whole target.
    void draw(VkCommandBuffer cmd, VkImageView target, VkExtent2D extent,
              const glm::mat4 (&light_from_world)[4]) const {
        vkt::begin_rendering(cmd, target, extent, {{0.1f, 0.1f, 0.12f, 1.0f}});
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);
        Push push{{extent.width, extent.height, cascades_, 0u}, {}};
        for (uint32_t c = 0; c < cascades_; ++c)
            push.near_depth[int(c)] = slice_near_depth(light_from_world[c]);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }

private:
    struct Push {
        glm::uvec4 size;       // x, y: the target's extent; z: the cascades
        glm::vec4 near_depth;  // each cascade's slice_near_depth: drawn black
    };
    uint32_t cascades_ = 1;
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};
