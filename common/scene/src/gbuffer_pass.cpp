// The G-buffer pass, taught in chapter 16 (book/16_deferred.md quotes most of
// this file) and reused by chapter 17.

#include "vkt/scene/gbuffer_pass.hpp"

#include "vkt/core/check.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <cstddef>
#include <iterator>
#include <string>

namespace vkt::deferred {

using vkt::shapes::Vertex;

const VkVertexInputBindingDescription SceneMeshes::vertex_binding{0, sizeof(Vertex),
                                                                  VK_VERTEX_INPUT_RATE_VERTEX};
const std::array<VkVertexInputAttributeDescription, 2> SceneMeshes::vertex_attributes{{
    {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
    {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
}};

SceneMeshes::SceneMeshes(const Gpu& gpu, VkDescriptorSetLayout frame_layout) {
    vkt::shapes::MeshBuilder builder;
    meshes_[floor_mesh] = builder.floor(4);
    meshes_[cube_mesh] = builder.cube();
    meshes_[sphere_mesh] = builder.sphere(24, 16);
    meshes_[cylinder_mesh] = builder.cylinder(24);
    meshes_[torus_mesh] = builder.torus(32, 12, 0.15f);
    vertex_buffer_ =
        create_device_buffer(gpu, builder.vertices.data(), builder.vertices.size() * sizeof(Vertex),
                             VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    index_buffer_ =
        create_device_buffer(gpu, builder.indices.data(), builder.indices.size() * sizeof(uint16_t),
                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT, 0, object_push_size};
    layout_ = create_pipeline_layout(gpu.device, {&frame_layout, 1}, {&range, 1});
}

void SceneMeshes::draw(VkCommandBuffer cmd, VkDescriptorSet frame_set,
                       std::span<const Object> objects) const {
    const VkBuffer vertex_buffer = vertex_buffer_.buffer;
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
    vkCmdBindIndexBuffer(cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &frame_set, 0,
                            nullptr);
    for (const Object& object : objects) {
        const ObjectPush push = object_push(object);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, object_push_size, &push);
        const vkt::shapes::MeshRange& mesh = meshes_[object.mesh];
        vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, 0);
    }
}

namespace {

// D32_SFLOAT must be both a depth attachment and sampled, R16G16_SNORM a
// colour attachment: desktop GPUs and lavapipe have both, but the
// specification does not promise them.
void check_formats(VkPhysicalDevice physical) {
    const struct {
        VkFormat format;
        VkFormatFeatureFlags features;
        const char* name;
    } wanted[] = {
        {depth_format,
         VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT,
         "VK_FORMAT_D32_SFLOAT as a sampled depth attachment"},
        {normal_format, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT,
         "VK_FORMAT_R16G16_SNORM as a colour attachment"},
    };
    for (const auto& w : wanted) {
        VkFormatProperties properties{};
        vkGetPhysicalDeviceFormatProperties(physical, w.format, &properties);
        if ((properties.optimalTilingFeatures & w.features) != w.features)
            throw Error(std::string("this device lacks ") + w.name);
    }
}

VkImageLayout read_layout(int image) {
    return image == 3 ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                      : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

}  // namespace

GBufferPass::GBufferPass(const Context& context, const SceneMeshes& scene,
                         VkPipelineStageFlags2 readers)
    : physical_(context.physical), device_(context.device), scene_(&scene), readers_(readers) {
    check_formats(physical_);
    ShaderModule scene_vert = load_shader(device_, context.chapter, "scene.vert");
    ShaderModule gbuffer_frag = load_shader(device_, context.chapter, "gbuffer.frag");
    // [pipelines]
    // The G-buffer pass: three colour attachments and depth, no blending.
    pipeline_ = create_graphics_pipeline(
        device_, {.vertex = scene_vert,
                  .fragment = gbuffer_frag,
                  .layout = scene.layout(),
                  .bindings = {&SceneMeshes::vertex_binding, 1},
                  .attributes = SceneMeshes::vertex_attributes,
                  .cull_mode = VK_CULL_MODE_BACK_BIT,
                  .color_formats = {std::begin(gbuffer_formats), std::end(gbuffer_formats)},
                  .depth_format = depth_format});
    // [/pipelines]
    // texelFetch ignores filtering, but a combined image sampler needs one.
    const VkSamplerCreateInfo sampler{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = VK_FILTER_NEAREST,
        .minFilter = VK_FILTER_NEAREST,
        .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
    };
    VkSampler handle = VK_NULL_HANDLE;
    VKT_CHECK(vkCreateSampler(device_, &sampler, nullptr, &handle));
    sampler_ = Sampler(device_, handle);
}

// [gbuffer-images]
// The G-buffer is written as colour (or depth) attachments, then read by
// the lighting pass as sampled images; --verify also copies it out.
void GBufferPass::resize(VkExtent2D extent) {
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    auto colour = [&](VkFormat format) {
        return create_image_2d(physical_, device_, format, extent,
                               usage | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                               VK_IMAGE_ASPECT_COLOR_BIT);
    };
    gbuffer_.base_colour = colour(base_colour_format);
    gbuffer_.normal = colour(normal_format);
    gbuffer_.material = colour(material_format);
    gbuffer_.depth = create_image_2d(physical_, device_, depth_format, extent,
                                     usage | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                     VK_IMAGE_ASPECT_DEPTH_BIT);
}
// [/gbuffer-images]

std::array<VkDescriptorSetLayoutBinding, 4> GBufferPass::bindings(VkShaderStageFlags stages) {
    std::array<VkDescriptorSetLayoutBinding, 4> out{};
    for (uint32_t binding = 0; binding < 4; ++binding)
        out[binding] = {binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stages, nullptr};
    return out;
}

// The lighting pass reads them in these layouts (see to_read).
void GBufferPass::write_descriptors(VkDescriptorSet set) const {
    const Image* images[] = {&gbuffer_.base_colour, &gbuffer_.normal, &gbuffer_.material,
                             &gbuffer_.depth};
    for (uint32_t binding = 0; binding < 4; ++binding)
        write_image_descriptor(device_, set, binding, images[binding]->view, sampler_,
                               read_layout(int(binding)));
}

// [barriers]
// What one barrier waits for and what it allows, and the layout change.
struct GBufferPass::Transition {
    VkPipelineStageFlags2 src_stage;
    VkAccessFlags2 src_access;
    VkPipelineStageFlags2 dst_stage;
    VkAccessFlags2 dst_access;
    VkImageLayout old_layout, new_layout;
};

// One barrier for each G-buffer image, all four in one call.
void GBufferPass::transition(VkCommandBuffer cmd, const Transition& colour,
                             const Transition& depth) const {
    const VkImage images[] = {gbuffer_.base_colour.image, gbuffer_.normal.image,
                              gbuffer_.material.image, gbuffer_.depth.image};
    VkImageMemoryBarrier2 barriers[4];
    for (int i = 0; i < 4; ++i) {
        const Transition& t = i < 3 ? colour : depth;
        barriers[i] = {
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = t.src_stage,
            .srcAccessMask = t.src_access,
            .dstStageMask = t.dst_stage,
            .dstAccessMask = t.dst_access,
            .oldLayout = t.old_layout,
            .newLayout = t.new_layout,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = images[i],
            .subresourceRange = {i < 3 ? VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT)
                                       : VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT),
                                 0, 1, 0, 1},
        };
    }
    const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                      .imageMemoryBarrierCount = 4,
                                      .pImageMemoryBarriers = barriers};
    vkCmdPipelineBarrier2(cmd, &dependency);
}

constexpr VkPipelineStageFlags2 fragment_tests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

// Before pass 1: the old contents are not needed (UNDEFINED), but the last
// frame may still be using the images: its lighting pass reading them
// (readers_: FRAGMENT_SHADER in chapter 16), its pass 1 writing them. Wait
// for both, then allow attachment writes.
void GBufferPass::to_write(VkCommandBuffer cmd) const {
    transition(
        cmd,
        {readers_ | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {readers_ | fragment_tests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, fragment_tests,
         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
         VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
}

// Between the passes: pass 1's attachment writes (colour output; depth,
// stored by the fragment tests) must be finished and made visible to the
// shaders of pass 2, and each image moves to a read-only layout.
void GBufferPass::to_read(VkCommandBuffer cmd) const {
    transition(
        cmd,
        {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
         readers_, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {fragment_tests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, readers_,
         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
         VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL});
}
// [/barriers]

// [gbuffer-pass]
// Pass 1: dynamic rendering into three colour attachments and depth. Each
// is cleared: where nothing is drawn, depth stays 1 and the lighting pass
// shows the background there.
void GBufferPass::draw(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent,
                       std::span<const Object> objects) const {
    VkRenderingAttachmentInfo colour[3];
    const VkImageView views[] = {gbuffer_.base_colour.view, gbuffer_.normal.view,
                                 gbuffer_.material.view};
    for (int i = 0; i < 3; ++i)
        colour[i] = {
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = views[i],
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 0.0f}}},
        };
    const VkRenderingAttachmentInfo depth{
        .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
        .imageView = gbuffer_.depth.view,
        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,  // kept: pass 2 reads it
        .clearValue = {.depthStencil = {1.0f, 0}},
    };
    const VkRenderingInfo rendering{
        .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
        .renderArea = {{0, 0}, extent},
        .layerCount = 1,
        .colorAttachmentCount = 3,  // fragment outputs 0, 1, 2
        .pColorAttachments = colour,
        .pDepthAttachment = &depth,
    };
    vkCmdBeginRendering(cmd, &rendering);
    set_viewport_and_scissor(cmd, extent);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    scene_->draw(cmd, frame_set, objects);
    vkCmdEndRendering(cmd);
}
// [/gbuffer-pass]

void GBufferPass::record(VkCommandBuffer cmd, VkDescriptorSet frame_set, VkExtent2D extent,
                         std::span<const Object> objects) const {
    to_write(cmd);
    draw(cmd, frame_set, extent, objects);
    to_read(cmd);
}

// [full-screen]
// Pass 2 draws into the frame's target alone; no depth.
void begin_full_screen(VkCommandBuffer cmd, VkImageView target, VkExtent2D extent) {
    begin_colour_rendering(cmd, target, extent,
                           VK_ATTACHMENT_LOAD_OP_DONT_CARE);  // every pixel is written
    set_viewport_and_scissor(cmd, extent);
}
// [/full-screen]

}  // namespace vkt::deferred
