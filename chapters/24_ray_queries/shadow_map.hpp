#pragma once
// Chapter 24's shadow map, the --shadows map path to compare the rays with:
// chapter 22's idea in its plainest form, one map of the whole scene (no
// cascades), depth-biased, sampled with comparison and filtered 3x3.

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <span>
#include <string>

namespace ch24 {

class ShadowMap {
public:
    static constexpr uint32_t size = 2048;  // texels per side
    static constexpr VkFormat format = VK_FORMAT_D32_SFLOAT;

    ShadowMap(const vkt::Gpu& gpu, const std::string& chapter) : device_(gpu.device) {
        image_ = vkt::create_image_2d(
            gpu.physical, gpu.device, format, {size, size},
            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
            VK_IMAGE_ASPECT_DEPTH_BIT);
        // Kept in SHADER_READ_ONLY between frames, whichever path draws: the
        // lit pipeline's descriptor set names it either way.
        vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
            vkt::image_barrier(cmd, image_.image, depth_range(), VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                               0, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        });
        const VkSamplerCreateInfo comparison{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
            .magFilter = VK_FILTER_NEAREST,
            .minFilter = VK_FILTER_NEAREST,
            .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER,
            .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER,
            .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER,
            .compareEnable = VK_TRUE,
            .compareOp = VK_COMPARE_OP_LESS_OR_EQUAL,
            .borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE,  // outside the map: lit
        };
        VkSampler sampler;
        VKT_CHECK(vkCreateSampler(device_, &comparison, nullptr, &sampler));
        sampler_ = vkt::Sampler(device_, sampler);

        const VkVertexInputBindingDescription binding{0, sizeof(vkt::shapes::Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        layout_ = vkt::create_pipeline_layout(device_, {}, {&push, 1});
        const vkt::ShaderModule vertex = vkt::load_shader(device_, chapter, "shadow.vert");
        pipeline_ = vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                            .layout = layout_,
                                                            .bindings = {&binding, 1},
                                                            .attributes = {&position, 1},
                                                            .depth_format = format,
                                                            .depth_bias_constant = 4.0f,
                                                            .depth_bias_slope = 4.0f});
    }

    // The light's orthographic view of a sphere around the whole scene
    // (centre, radius), looking along light_dir: Vulkan clip space, depth 0
    // nearest the light.
    static glm::mat4 light_from_world(glm::vec3 centre, float radius, glm::vec3 light_dir) {
        const glm::mat4 view = glm::lookAt(centre - light_dir * radius, centre, {0, 1, 0});
        glm::mat4 ortho(1.0f);
        ortho[0][0] = 1.0f / radius;
        ortho[1][1] = 1.0f / radius;
        ortho[2][2] = -0.5f / radius;
        return ortho * view;
    }

    VkImageView view() const { return image_.view; }
    VkSampler sampler() const { return sampler_; }

    // Records the depth pass: one draw per (object transform, mesh), the
    // geometry buffers already bound. Leaves the map ready for the lit
    // pass's fragment shader.
    template <typename Draws>
    void record(VkCommandBuffer cmd, const glm::mat4& light_from_world, const Draws& draws) {
        constexpr VkPipelineStageFlags2 tests = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        vkt::image_barrier(cmd, image_.image, depth_range(), VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, tests,
                           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
        const VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = image_.view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.depthStencil = {1.0f, 0}},
        };
        const VkRenderingInfo pass{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                   .renderArea = {{0, 0}, {size, size}},
                                   .layerCount = 1,
                                   .pDepthAttachment = &depth};
        vkCmdBeginRendering(cmd, &pass);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(cmd, {size, size});
        for (const auto& draw : draws) {
            const glm::mat4 clip = light_from_world * draw.world_from_object;
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof clip, &clip);
            vkCmdDrawIndexed(cmd, draw.mesh.index_count, 1, draw.mesh.first_index, 0, 0);
        }
        vkCmdEndRendering(cmd);
        vkt::image_barrier(
            cmd, image_.image, depth_range(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, tests,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }

private:
    static VkImageSubresourceRange depth_range() { return {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1}; }

    VkDevice device_;
    vkt::Image image_;
    vkt::Sampler sampler_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace ch24
