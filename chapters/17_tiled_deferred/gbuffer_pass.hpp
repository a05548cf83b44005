#pragma once
// Chapter 16's pass 1, packed into a class for chapter 17: the scene's meshes,
// the G-buffer's four images, the pipeline (chapter 16's own scene.vert and
// gbuffer.frag) and the barriers around the pass. Chapter 16's main.cpp
// explains every line; the only change is that the G-buffer is read by
// compute shaders too (the tile pass), so the barriers name both stages.

#include "vkt/core/barrier.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/deferred_scene.hpp"

#include <cstddef>
#include <iterator>
#include <vector>

namespace ch17 {

using vkt::shapes::MeshRange;
using vkt::shapes::Vertex;

constexpr VkFormat gbuffer_formats[] = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R16G16_SNORM,
                                        VK_FORMAT_R8G8B8A8_UNORM};
constexpr VkFormat depth_format = VK_FORMAT_D32_SFLOAT;

class GBufferPass {
public:
    // The images: base colour, normal, material, depth.
    vkt::Image images[4];

    GBufferPass(const vkt::Context& context, VkDescriptorSetLayout frame_layout)
        : physical_(context.physical), device_(context.device) {
        vkt::shapes::MeshBuilder builder;
        meshes_[vkt::deferred::floor_mesh] = builder.floor(4);
        meshes_[vkt::deferred::cube_mesh] = builder.cube();
        meshes_[vkt::deferred::sphere_mesh] = builder.sphere(24, 16);
        meshes_[vkt::deferred::cylinder_mesh] = builder.cylinder(24);
        meshes_[vkt::deferred::torus_mesh] = builder.torus(32, 12, 0.15f);
        const vkt::Gpu gpu = context.gpu();
        vertex_buffer_ = vkt::create_device_buffer(gpu, builder.vertices.data(),
                                                   builder.vertices.size() * sizeof(Vertex),
                                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ = vkt::create_device_buffer(gpu, builder.indices.data(),
                                                  builder.indices.size() * sizeof(uint16_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT, 0,
                                        vkt::deferred::object_push_size};
        layout_ = vkt::create_pipeline_layout(device_, {&frame_layout, 1}, {&range, 1});
        vkt::ShaderModule vert = vkt::load_shader(device_, "17_tiled_deferred", "scene.vert");
        vkt::ShaderModule frag = vkt::load_shader(device_, "17_tiled_deferred", "gbuffer.frag");
        const VkVertexInputBindingDescription input{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
        };
        pipeline_ = vkt::create_graphics_pipeline(
            device_, {.vertex = vert,
                      .fragment = frag,
                      .layout = layout_,
                      .bindings = {&input, 1},
                      .attributes = attributes,
                      .cull_mode = VK_CULL_MODE_BACK_BIT,
                      .color_formats = {std::begin(gbuffer_formats), std::end(gbuffer_formats)},
                      .depth_format = depth_format});
    }

    void resize(VkExtent2D extent) {
        const VkImageUsageFlags usage =
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        for (int i = 0; i < 3; ++i)
            images[i] = vkt::create_image_2d(physical_, device_, gbuffer_formats[i], extent,
                                             usage | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                             VK_IMAGE_ASPECT_COLOR_BIT);
        images[3] = vkt::create_image_2d(physical_, device_, depth_format, extent,
                                         usage | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                         VK_IMAGE_ASPECT_DEPTH_BIT);
    }

    static VkImageLayout read_layout(int i) {
        return i == 3 ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                      : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    }

    // Barriers, pass 1, barriers: afterwards the G-buffer may be read by
    // fragment and compute shaders.
    void record(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent,
                const std::vector<vkt::deferred::Object>& objects) const {
        constexpr auto readers =
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        constexpr auto tests = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                               VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        constexpr auto colour_out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        constexpr auto colour_write = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        constexpr auto depth_write = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        for (int i = 0; i < 3; ++i)
            vkt::image_barrier(cmd, images[i].image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, readers | colour_out,
                               colour_write, colour_out, colour_write);
        vkt::image_barrier(cmd, images[3].image, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, readers | tests, depth_write,
                           tests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | depth_write,
                           VK_IMAGE_ASPECT_DEPTH_BIT);
        VkRenderingAttachmentInfo colour[3];
        for (int i = 0; i < 3; ++i)
            colour[i] = {
                .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                .imageView = images[i].view,
                .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 0.0f}}},
            };
        const VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = images[3].view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.depthStencil = {1.0f, 0}},
        };
        const VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .renderArea = {{0, 0}, extent},
            .layerCount = 1,
            .colorAttachmentCount = 3,
            .pColorAttachments = colour,
            .pDepthAttachment = &depth,
        };
        vkCmdBeginRendering(cmd, &rendering);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frame_set, 0,
                                nullptr);
        for (const vkt::deferred::Object& object : objects) {
            const vkt::deferred::ObjectPush push = vkt::deferred::object_push(object);
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0,
                               vkt::deferred::object_push_size, &push);
            const MeshRange& mesh = meshes_[object.mesh];
            vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, 0);
        }
        vkCmdEndRendering(cmd);
        for (int i = 0; i < 3; ++i)
            vkt::image_barrier(cmd, images[i].image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                               read_layout(i), colour_out, colour_write, readers,
                               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        vkt::image_barrier(cmd, images[3].image, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                           read_layout(3), tests, depth_write, readers,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    MeshRange meshes_[vkt::deferred::mesh_count];
    vkt::Buffer vertex_buffer_, index_buffer_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace ch17
