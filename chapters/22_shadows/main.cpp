// Chapter 22: shadow maps.
//
// A point is in shadow when something lies between it and the light. A
// shadow map answers that for a whole frame at once: first the scene is
// drawn from the light, depth only, into an image (the shadow map) that then
// holds, for every direction the light shines in, how far it reaches. The lit
// pass looks each point up in that map and compares. This file draws a long
// floor with rows of pillars under a directional light. By default one map
// covers the whole view (book/22_shadows.md); --cascades N splits the view
// into N cascades, each with its own map (one layer of an array image) fitted
// to its part of the view, so that shadows near the camera get as many
// texels as those far away (book/22b_cascades.md).

#include "cascades.hpp"
#include "map_view.hpp"
#include "scene.hpp"
#include "uniforms.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/meshes.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr uint32_t shadow_size = 1024;  // texels per side of each cascade's map
constexpr float z_near = 0.1f, z_far = 60.0f;

class Shadows : public vkt::Renderer {
public:
    explicit Shadows(const vkt::Context& context)
        : physical_(context.physical),
          device_(context.device),
          cascades_(uint32_t(context.options.integer("--cascades"))),
          colour_cascades_(context.options.text("--view") == "cascades"),
          show_map_(context.options.text("--view") == "map") {
        vkt::shapes::MeshBuilder meshes;
        draws_ = make_scene(meshes);
        const vkt::Gpu gpu = context.gpu();
        vertices_ = vkt::create_device_buffer(gpu, meshes.vertices.data(),
                                              meshes.vertices.size() * sizeof(vkt::shapes::Vertex),
                                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        indices_ = vkt::create_device_buffer(gpu, meshes.indices.data(),
                                             meshes.indices.size() * sizeof(uint16_t),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        // [shadow-map]
        // One depth image, one layer per cascade, rendered into as a depth
        // attachment and then sampled: a view of each layer to render into,
        // and one of the whole array for the lit pass.
        shadow_format_ = VK_FORMAT_D32_SFLOAT;
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(physical_, shadow_format_, &properties);
        const VkFormatFeatureFlags needed =
            VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
        if ((properties.optimalTilingFeatures & needed) != needed)
            throw vkt::Error("VK_FORMAT_D32_SFLOAT cannot be a sampled depth attachment here");
        const VkImageCreateInfo image_info{
            .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
            .imageType = VK_IMAGE_TYPE_2D,
            .format = shadow_format_,
            .extent = {shadow_size, shadow_size, 1},
            .mipLevels = 1,
            .arrayLayers = cascades_,
            .samples = VK_SAMPLE_COUNT_1_BIT,
            .tiling = VK_IMAGE_TILING_OPTIMAL,
            .usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
            .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
            .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
        };
        VkImage image;
        VKT_CHECK(vkCreateImage(device_, &image_info, nullptr, &image));
        shadow_image_ = vkt::ImageHandle(device_, image);
        VkMemoryRequirements requirements;
        vkGetImageMemoryRequirements(device_, image, &requirements);
        shadow_memory_ = vkt::allocate_memory(physical_, device_, requirements,
                                              VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VKT_CHECK(vkBindImageMemory(device_, image, shadow_memory_, 0));
        for (uint32_t layer = 0; layer <= cascades_; ++layer) {
            const bool whole = layer == cascades_;  // the last view: every layer
            const VkImageViewCreateInfo view_info{
                .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                .image = image,
                .viewType = whole ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
                .format = shadow_format_,
                .subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, whole ? 0 : layer,
                                     whole ? cascades_ : 1},
            };
            VkImageView view;
            VKT_CHECK(vkCreateImageView(device_, &view_info, nullptr, &view));
            shadow_views_.emplace_back(device_, view);
        }
        // [/shadow-map]

        // [sampler]
        // A comparison sampler: texture() returns not the stored depth but
        // whether the given depth passes compareOp against it (1 or 0).
        // Outside the map the border's depth 1.0 lets every point pass: lit.
        const VkSamplerCreateInfo sampler_info{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
            .magFilter = VK_FILTER_NEAREST,
            .minFilter = VK_FILTER_NEAREST,
            .mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST,
            .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER,
            .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER,
            .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
            .compareEnable = VK_TRUE,
            .compareOp = VK_COMPARE_OP_LESS_OR_EQUAL,
            .borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE,
        };
        VkSampler sampler;
        VKT_CHECK(vkCreateSampler(device_, &sampler_info, nullptr, &sampler));
        sampler_ = vkt::Sampler(device_, sampler);
        // [/sampler]

        frame_buffer_ =
            vkt::create_host_buffer(gpu, sizeof(FrameBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
             VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}};
        pool_ = vkt::create_descriptor_pool(device_, 1, sizes);
        set_ = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
        vkt::write_buffer_descriptor(device_, set_, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                     frame_buffer_.buffer, 0, sizeof(FrameBlock));
        vkt::write_image_descriptor(device_, set_, 1, shadow_views_.back(), sampler_,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

        const VkVertexInputBindingDescription binding{0, sizeof(vkt::shapes::Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, normal)},
        };
        const VkPushConstantRange shadow_push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        shadow_layout_ = vkt::create_pipeline_layout(device_, {}, {&shadow_push, 1});
        shadow_vertex_ = vkt::load_shader(device_, context.chapter, "shadow.vert");
        bias_constant_ = float(context.options.number("--bias-constant"));
        bias_slope_ = float(context.options.number("--bias-slope"));
        create_shadow_pipeline();

        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                       sizeof(glm::mat4) + sizeof(glm::vec4)};
        const VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device_, set_layouts, {&push, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "scene.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "scene.frag");
        depth_format_ = vkt::choose_depth_format(physical_);
        pipeline_ = vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                            .fragment = fragment,
                                                            .layout = layout_,
                                                            .bindings = {&binding, 1},
                                                            .attributes = attributes,
                                                            .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                            .color_formats = {context.color_format},
                                                            .depth_format = depth_format_});
        if (show_map_)
            map_view_ = MapView(device_, context.chapter, context.color_format,
                                shadow_views_.back(), cascades_);
        resize(context.extent);
        std::fprintf(stderr,
                     "22_shadows: %u cascade%s of %ux%u, splits at %.1f %.1f %.1f %.1f, bias %.2f "
                     "+ %.2f x slope%s\n",
                     cascades_, cascades_ == 1 ? "" : "s", shadow_size, shadow_size,
                     block_.splits[0], block_.splits[1], block_.splits[2], block_.splits[3],
                     bias_constant_, bias_slope_,
                     colour_cascades_ ? ", cascades coloured"
                     : show_map_      ? ", the shadow map shown"
                                      : "");
    }

    // [overlay]
    // In a window (chapter 21's overlay): the cascade colours, a setting of
    // the uniform block, and the depth bias, baked into the shadow pipeline.
    // One uniform buffer and one shadow pipeline serve every frame in
    // flight, so a change waits for the GPU to finish them before it
    // rewrites the one or makes the other again.
    void overlay(vkt::OverlayPanel& panel) override {
        const bool colours = panel.checkbox("Colour the cascades", colour_cascades_);
        bool bias = panel.slider("Bias constant", bias_constant_, 0.0f, 8.0f);
        bias = panel.slider("Bias slope", bias_slope_, 0.0f, 150.0f) || bias;
        panel.text(std::to_string(cascades_) + (cascades_ == 1 ? " cascade" : " cascades") +
                   " (--cascades, at start-up)");
        if (!colours && !bias) return;
        VKT_CHECK(vkDeviceWaitIdle(device_));
        block_.settings.y = colour_cascades_ ? 1u : 0u;
        std::memcpy(frame_buffer_.mapped, &block_, sizeof block_);
        if (bias) create_shadow_pipeline();
    }
    // [/overlay]

    // The camera and the cascades follow the target's shape; the GPU is idle.
    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
        // [fit-cascades]
        const glm::vec3 forward = glm::normalize(glm::vec3(0.0f, -0.25f, -1.0f));
        const Camera c{.eye = {0.0f, 3.0f, 8.0f},
                       .forward = forward,
                       .up = glm::normalize(glm::cross(glm::cross(forward, {0, 1, 0}), forward)),
                       .fov_y = glm::radians(50.0f),
                       .aspect = float(extent.width) / float(extent.height),
                       .z_near = z_near,
                       .z_far = z_far};
        const glm::vec3 light = light_direction();
        const std::vector<float> splits = cascade_splits(z_near, z_far, cascades_, 0.6f);
        for (uint32_t i = 0; i < cascades_; ++i)
            block_.light_from_world[i] = light_from_world(
                slice_corners(c, splits[i], splits[i + 1]), light, 40.0f, shadow_size);
        // [/fit-cascades]
        for (uint32_t i = 0; i < 4; ++i) block_.splits[int(i)] = splits[std::min(i + 1, cascades_)];
        block_.clip_from_world = vkt::vulkan_perspective(c.fov_y, c.aspect, z_near, z_far) *
                                 glm::lookAt(c.eye, c.eye + c.forward, glm::vec3(0, 1, 0));
        block_.eye = glm::vec4(c.eye, 1);
        block_.forward = glm::vec4(c.forward, 0);
        block_.light = glm::vec4(light, 0);
        block_.settings = {cascades_, colour_cascades_ ? 1u : 0u, 0u, 0u};
        std::memcpy(frame_buffer_.mapped, &block_, sizeof block_);
    }

    void record(const vkt::Frame& frame) override {
        const VkCommandBuffer cmd = frame.cmd;
        const VkImageSubresourceRange layers{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, cascades_};
        constexpr VkPipelineStageFlags2 tests = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        // [shadow-before]
        // The map is rewritten each frame: after the last frame's lit pass
        // has read it (fragment shader), its old contents are thrown away.
        vkt::image_barrier(cmd, shadow_image_, layers, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0, tests,
                           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
        bind_geometry(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shadow_pipeline_);
        vkt::set_viewport_and_scissor(cmd, {shadow_size, shadow_size});
        // [/shadow-before]
        // [shadow-loop]
        {  // --benchmark's GPU time of the shadow pass, every cascade
            auto scope = frame.gpu_scope("shadow");
            for (uint32_t c = 0; c < cascades_; ++c) {
                // [shadow-layer]
                const VkRenderingAttachmentInfo depth{
                    .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                    .imageView = shadow_views_[c],
                    .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                    .storeOp = VK_ATTACHMENT_STORE_OP_STORE,  // the lit pass reads it
                    .clearValue = {.depthStencil = {1.0f, 0}},
                };
                const VkRenderingInfo rendering{
                    .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                    .renderArea = {{0, 0}, {shadow_size, shadow_size}},
                    .layerCount = 1,
                    .pDepthAttachment = &depth,
                };
                vkCmdBeginRendering(cmd, &rendering);
                for (const Draw& draw : draws_) {
                    const glm::mat4 clip = block_.light_from_world[c] * draw.world_from_object;
                    vkCmdPushConstants(cmd, shadow_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0,
                                       sizeof clip, &clip);
                    vkCmdDrawIndexed(cmd, draw.mesh.index_count, 1, draw.mesh.first_index, 0, 0);
                }
                vkCmdEndRendering(cmd);
                // [/shadow-layer]
            }
        }
        // [/shadow-loop]
        // [shadow-after]
        // Depth writes to shader reads: the lit pass's fragment shader must
        // see every layer complete.
        vkt::image_barrier(cmd, shadow_image_, layers, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                           VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, tests,
                           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        // [/shadow-after]

        if (show_map_) {  // --view map: the map itself instead of the scene
            map_view_.draw(cmd, frame.target_view, frame.extent, block_.light_from_world);
            return;
        }
        auto scope = frame.gpu_scope("lit");
        vkt::begin_depth_frame(cmd, depth_.image);
        vkt::begin_rendering(cmd, frame.target_view, frame.extent, {{0.45f, 0.6f, 0.8f, 1.0f}},
                             depth_.view);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(cmd, frame.extent);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);
        for (const Draw& draw : draws_) {
            vkCmdPushConstants(cmd, layout_,
                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(glm::mat4) + sizeof(glm::vec4), &draw);
            vkCmdDrawIndexed(cmd, draw.mesh.index_count, 1, draw.mesh.first_index, 0, 0);
        }
        vkCmdEndRendering(cmd);
    }

private:
    void bind_geometry(VkCommandBuffer cmd) const {
        const VkBuffer buffer = vertices_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT16);
    }

    void create_shadow_pipeline() {
        const VkVertexInputBindingDescription binding{0, sizeof(vkt::shapes::Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription position{0, 0, VK_FORMAT_R32G32B32_SFLOAT,
                                                         offsetof(vkt::shapes::Vertex, position)};
        // [shadow-pipeline]
        // Depth only (no fragment shader, no colour attachment), nothing
        // culled (a caster's back faces cast too), and the depth bias: each
        // depth written is pushed away from the light by `constant` steps of
        // the format plus `slope` times the triangle's depth slope, so that a
        // lit surface does not shadow itself where the map's texels are
        // coarser than the screen's pixels (shadow acne).
        shadow_pipeline_ =
            vkt::create_graphics_pipeline(device_, {.vertex = shadow_vertex_,
                                                    .layout = shadow_layout_,
                                                    .bindings = {&binding, 1},
                                                    .attributes = {&position, 1},
                                                    .depth_format = shadow_format_,
                                                    .depth_bias_constant = bias_constant_,
                                                    .depth_bias_slope = bias_slope_});
        // [/shadow-pipeline]
    }

    VkPhysicalDevice physical_;
    VkDevice device_;
    uint32_t cascades_;
    bool colour_cascades_;
    bool show_map_;
    MapView map_view_;                                // --view map
    float bias_constant_ = 0.0f, bias_slope_ = 0.0f;  // the shadow pipeline's depth bias
    vkt::ShaderModule shadow_vertex_;                 // kept: the overlay remakes that pipeline
    std::vector<Draw> draws_;
    vkt::Buffer vertices_, indices_, frame_buffer_;
    FrameBlock block_{};
    VkFormat shadow_format_ = VK_FORMAT_UNDEFINED, depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::DeviceMemory shadow_memory_;  // freed after the image and its views
    vkt::ImageHandle shadow_image_;
    std::vector<vkt::ImageView> shadow_views_;  // after the image: destroyed first
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vkt::Image depth_;
    vkt::PipelineLayout shadow_layout_, layout_;
    vkt::Pipeline shadow_pipeline_, pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "22_shadows", .title = "22 - Shadow maps"};
    spec.overlay = true;  // in a window: the cascade colours and the depth bias, live
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        {.name = "--cascades",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many cascades split the view (1..4); 1 is one map for the whole "
                 "view (chapter 22), 22b uses 3",
         .default_value = "1",
         .min = 1,
         .max = 4},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "lit: the scene; cascades: each cascade tinted its own colour; map: the "
                 "shadow map's depth, cascade by cascade",
         .default_value = "lit",
         .choices = {"lit", "cascades", "map"}},
        {.name = "--bias-constant",
         .type = vkt::OptionType::number,
         .value_name = "F",
         .help = "depthBiasConstantFactor of the shadow pass (0..1000)",
         .default_value = "4",
         .min = 0,
         .max = 1000},
        {.name = "--bias-slope",
         .type = vkt::OptionType::number,
         .value_name = "F",
         .help = "depthBiasSlopeFactor of the shadow pass (0..200)",
         .default_value = "4",
         .min = 0,
         .max = 200},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Shadows>(context);
    });
}
