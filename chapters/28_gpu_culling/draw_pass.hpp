#pragma once
// Chapter 28's drawing, apart from its indirect draws: the push constants
// every pass shares, the rendering the early and the late pass begin (the
// late one loads what the early one stored), and the three graphics
// pipelines (the shapes, the occluded shapes in red, the pyramid's view).

#include "vkt/core/owned.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace ch28 {

// Must match culling_data.glsl.
struct Push {
    glm::mat4 clip_from_world;
    uint32_t instance_count, phase, mode, list;
    glm::uvec2 viewport, pyramid;
    uint32_t levels, show_level;
    uint32_t meshlet_cull, pad;  // the task path: 1 tests each meshlet (task_path.hpp)
    glm::vec3 eye;               // ... the normal cone against the camera's position
};
static_assert(sizeof(Push) == 124);

// The stages that read the push constants and set 0; the task path adds
// the task and mesh stages.
constexpr VkShaderStageFlags kStages =
    VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// [begin-pass]
// Colour and depth, cleared (depth reversed: to 0, the far plane) or loaded,
// and both stored: the late pass and the pyramid read them on. This is not
// vkt::begin_rendering, which clears depth to 1 and does not store it.
inline void begin_pass(VkCommandBuffer cmd, VkImageView target, VkImageView depth_view,
                       VkExtent2D extent, VkAttachmentLoadOp load) {
    const VkRenderingAttachmentInfo colour{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = target,
        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        .loadOp = load,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue = {.color = {{0.55f, 0.70f, 0.90f, 1.0f}}},
    };
    const VkRenderingAttachmentInfo depth{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = depth_view,
        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        .loadOp = load,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        .clearValue = {.depthStencil = {0.0f, 0}},
    };
    const VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                    .renderArea = {{0, 0}, extent},
                                    .layerCount = 1,
                                    .colorAttachmentCount = 1,
                                    .pColorAttachments = &colour,
                                    .pDepthAttachment = &depth};
    vkCmdBeginRendering(cmd, &rendering);
}
// [/begin-pass]

struct DrawPipelines {
    vkt::Pipeline shapes, culled, pyramid;
};

// Chapter 08's pipeline, reversed: GREATER passes the nearer. The culled
// view's draws ignore depth, to show what lies behind; the pyramid view is
// a full-screen triangle.
inline DrawPipelines make_draw_pipelines(VkDevice device, std::string_view chapter,
                                         VkPipelineLayout layout, VkFormat color_format,
                                         VkFormat depth_format) {
    vkt::ShaderModule vertex = vkt::load_shader(device, chapter, "draw.vert");
    vkt::ShaderModule fragment = vkt::load_shader(device, chapter, "draw.frag");
    const VkVertexInputBindingDescription binding{0, sizeof(vkt::shapes::Vertex),
                                                  VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, normal)},
    };
    vkt::GraphicsPipelineDesc desc{.vertex = vertex,
                                   .fragment = fragment,
                                   .layout = layout,
                                   .bindings = {&binding, 1},
                                   .attributes = attributes,
                                   .cull_mode = VK_CULL_MODE_BACK_BIT,
                                   .color_formats = {color_format},
                                   .depth_format = depth_format,
                                   .depth_compare = VK_COMPARE_OP_GREATER};
    DrawPipelines pipelines;
    pipelines.shapes = vkt::create_graphics_pipeline(device, desc);
    desc.depth_write = false;
    desc.depth_compare = VK_COMPARE_OP_ALWAYS;
    pipelines.culled = vkt::create_graphics_pipeline(device, desc);
    vkt::ShaderModule full_screen = vkt::load_shader(device, chapter, "pyramid_view.vert");
    vkt::ShaderModule level = vkt::load_shader(device, chapter, "pyramid_view.frag");
    pipelines.pyramid = vkt::create_graphics_pipeline(device, {.vertex = full_screen,
                                                               .fragment = level,
                                                               .layout = layout,
                                                               .color_formats = {color_format}});
    return pipelines;
}

// One set for every pass: instances, meshes, lists, counts, visibility
// (bindings 0-4), and the pyramid (binding 5, written when it is made).
struct CullingSet {
    vkt::DescriptorSetLayout layout;
    vkt::DescriptorPool pool;
    VkDescriptorSet set = VK_NULL_HANDLE;
};
inline CullingSet make_culling_set(VkDevice device, VkShaderStageFlags stages,
                                   const std::array<VkBuffer, 5>& buffers) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (uint32_t b = 0; b < 5; ++b)
        bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr});
    bindings.push_back({5, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr});
    CullingSet culling;
    culling.layout = vkt::create_descriptor_set_layout(device, bindings);
    const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 5},
                                          {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
    culling.pool = vkt::create_descriptor_pool(device, 1, sizes);
    culling.set = vkt::allocate_descriptor_set(device, culling.pool, culling.layout);
    for (uint32_t b = 0; b < 5; ++b)
        vkt::write_buffer_descriptor(device, culling.set, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     buffers[b], 0, VK_WHOLE_SIZE);
    return culling;
}

// --view pyramid: one level over the whole picture, a full-screen triangle.
inline void show_pyramid(VkCommandBuffer cmd, VkImageView target, VkExtent2D extent,
                         VkPipeline pipeline, VkPipelineLayout layout, VkShaderStageFlags stages,
                         VkDescriptorSet set, const Push& push) {
    vkt::begin_colour_rendering(cmd, target, extent, VK_ATTACHMENT_LOAD_OP_DONT_CARE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, layout, stages, 0, sizeof(Push), &push);
    vkt::set_viewport_and_scissor(cmd, extent);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace ch28
