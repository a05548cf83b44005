// Chapter 16: deferred shading.
//
// The scene of a few shapes on a floor, under many moving point lights, drawn
// in two passes. Pass 1 draws the geometry once and writes, for each pixel,
// what lighting needs to know about the visible surface into the G-buffer:
// base colour, normal, material parameters, and depth. Pass 2 draws one
// full-screen triangle and lights each pixel from the G-buffer, so every
// light is evaluated once per pixel, never for a hidden surface. The barrier
// between the passes is written out here. --path forward draws the same scene
// the classic way, lighting each fragment as it is drawn, for comparison.
//
// The lighting is chapter 12's (shaders/common/lighting.glsl, vkt/scene/lighting.hpp)
// with its windowed falloff; the lights live in a storage buffer, up to 65,536.

#include "vkt/core/barrier.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/deferred_blocks.hpp"
#include "vkt/scene/deferred_scene.hpp"
#include "vkt/scene/deferred_verify.hpp"
#include "vkt/scene/gbuffer.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace {

using vkt::shapes::MeshRange;
using vkt::shapes::Vertex;
using namespace vkt::deferred;  // chapter 16's blocks, scene and checks

// Our own limit: 65,536 lights of 32 bytes are 2 MiB per frame in flight, far
// below maxStorageBufferRange (the specification promises at least 128 MiB).
constexpr uint32_t max_lights = 65536;

// [formats]
// The G-buffer: 16 bytes per pixel in all.
constexpr VkFormat base_colour_format = VK_FORMAT_R8G8B8A8_SRGB;  // 4 B: albedo, sRGB-encoded
constexpr VkFormat normal_format = VK_FORMAT_R16G16_SNORM;        // 4 B: octahedral normal
constexpr VkFormat material_format = VK_FORMAT_R8G8B8A8_UNORM;    // 4 B: specular, shininess
constexpr VkFormat depth_format = VK_FORMAT_D32_SFLOAT;           // 4 B: depth, sampled later
// [/formats]
const VkFormat gbuffer_formats[] = {base_colour_format, normal_format, material_format};
// --verify renders into float targets, so that nothing is clamped or rounded.
constexpr VkFormat verify_format = VK_FORMAT_R32G32B32A32_SFLOAT;

const glm::vec3 eye(0.0f, 6.0f, 10.0f);

// One G-buffer: its four images.
struct GBuffer {
    vkt::Image base_colour, normal, material, depth;
};

class Deferred : public vkt::Renderer {
public:
    explicit Deferred(const vkt::Context& context)
        : gpu_(context.gpu()),
          physical_(context.physical),
          device_(context.device),
          chapter_(context.chapter),
          colour_format_(context.color_format),
          slots_(context.frames_in_flight),
          max_storage_range_(context.properties.limits.maxStorageBufferRange) {
        const vkt::Options& options = context.options;
        forward_ = options.text("--path") == "forward";
        light_count_ = uint32_t(options.integer("--lights"));
        const std::string view = options.text("--view");
        const char* views[] = {"lit", "albedo", "normal", "material", "depth"};
        for (int32_t i = 0; i < 5; ++i)
            if (view == views[i]) view_ = i;
        if (forward_ && view_ != vkt::deferred::view_lit)
            throw vkt::Error("--view " + view +
                             " shows a G-buffer target: it needs --path deferred");
        if (options.has("--verify")) verify_ = options.text("--verify");
        if (!verify_.empty() && forward_)
            throw vkt::Error("--verify renders both paths itself: leave out --path forward");
        verify_frame_ = options.frames.value_or(1) - 1;
        std::fprintf(stderr, "16_deferred: %u light%s, path %s, view %s\n", light_count_,
                     light_count_ == 1 ? "" : "s", forward_ ? "forward" : "deferred", view.c_str());
        check_formats();

        vkt::shapes::MeshBuilder builder;
        meshes_[floor_mesh] = builder.floor(4);
        meshes_[cube_mesh] = builder.cube();
        meshes_[sphere_mesh] = builder.sphere(24, 16);
        meshes_[cylinder_mesh] = builder.cylinder(24);
        meshes_[torus_mesh] = builder.torus(32, 12, 0.15f);
        const vkt::Gpu& gpu = gpu_;
        vertex_buffer_ = vkt::create_device_buffer(gpu, builder.vertices.data(),
                                                   builder.vertices.size() * sizeof(Vertex),
                                                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ = vkt::create_device_buffer(gpu, builder.indices.data(),
                                                  builder.indices.size() * sizeof(uint16_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        create_descriptors();
        create_pipelines();
        resize(context.extent);
    }

    // [gbuffer-images]
    // The G-buffer is written as colour (or depth) attachments, then read by
    // the lighting pass as sampled images; --verify also copies it out.
    void resize(VkExtent2D extent) override {
        const VkImageUsageFlags usage =
            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        auto colour = [&](VkFormat format) {
            return vkt::create_image_2d(physical_, device_, format, extent,
                                        usage | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                        VK_IMAGE_ASPECT_COLOR_BIT);
        };
        gbuffer_.base_colour = colour(base_colour_format);
        gbuffer_.normal = colour(normal_format);
        gbuffer_.material = colour(material_format);
        gbuffer_.depth = vkt::create_image_2d(physical_, device_, depth_format, extent,
                                              usage | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                              VK_IMAGE_ASPECT_DEPTH_BIT);
        // The lighting pass reads them in these layouts (see gbuffer_to_read).
        const vkt::Image* images[] = {&gbuffer_.base_colour, &gbuffer_.normal, &gbuffer_.material,
                                      &gbuffer_.depth};
        for (uint32_t binding = 0; binding < 4; ++binding)
            vkt::write_image_descriptor(device_, gbuffer_set_, binding, images[binding]->view,
                                        sampler_,
                                        binding == 3 ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                                                     : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        forward_depth_ = vkt::create_depth_image(physical_, device_, depth_format, extent);
    }
    // [/gbuffer-images]

    void record(const vkt::Frame& frame) override {
        update(frame.slot, frame.extent, float(frame.time));
        if (!verify_.empty() && frame.index == verify_frame_) verify(frame);
        const VkCommandBuffer cmd = frame.cmd;
        if (forward_) {
            auto scope = frame.gpu_scope("forward");
            vkt::begin_depth_frame(cmd, forward_depth_.image);
            draw_forward(cmd, frame.slot, frame.extent, frame.target_view, pipelines_.forward);
            return;
        }
        // [deferred-frame]
        {
            auto scope = frame.gpu_scope("gbuffer");
            gbuffer_to_write(cmd);
            draw_gbuffer(cmd, frame.slot, frame.extent);
            gbuffer_to_read(cmd);
        }
        auto scope = frame.gpu_scope("lighting");
        draw_lighting(cmd, frame.slot, frame.extent, frame.target_view, pipelines_.lighting,
                      {view_, 0, light_count_, 1.0f});
        // [/deferred-frame]
    }

private:
    // D32_SFLOAT must be both a depth attachment and sampled, R16G16_SNORM a
    // colour attachment: desktop GPUs and lavapipe have both, but the
    // specification does not promise them.
    void check_formats() const {
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
            vkGetPhysicalDeviceFormatProperties(physical_, w.format, &properties);
            if ((properties.optimalTilingFeatures & w.features) != w.features)
                throw vkt::Error(std::string("this device lacks ") + w.name);
        }
    }

    // Set 0, one per frame in flight: the frame's uniforms and its lights.
    // Set 1, one for all frames: the G-buffer, read by the lighting pass.
    void create_descriptors() {
        const vkt::Gpu& gpu = gpu_;
        const VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
        const VkDescriptorSetLayoutBinding frame_bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        };
        frame_layout_ = vkt::create_descriptor_set_layout(device_, frame_bindings);
        std::vector<VkDescriptorSetLayoutBinding> gbuffer_bindings;
        for (uint32_t binding = 0; binding < 4; ++binding)
            gbuffer_bindings.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr});
        gbuffer_layout_ = vkt::create_descriptor_set_layout(device_, gbuffer_bindings);

        const uint32_t slots = slots_;
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slots},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slots},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}};
        pool_ = vkt::create_descriptor_pool(device_, slots + 1, sizes);
        // --verify also needs a copy of the lights moved out of reach (see verify).
        const VkDeviceSize lights_size =
            VkDeviceSize{light_count_} * sizeof(vkt::PointLight) * (verify_.empty() ? 1 : 2);
        if (lights_size > max_storage_range_)
            throw vkt::Error("--lights " + std::to_string(light_count_) +
                             ": more than this device's maxStorageBufferRange allows");
        for (uint32_t i = 0; i < slots; ++i) {
            uniforms_.push_back(vkt::create_host_buffer(gpu, sizeof(FrameUniforms),
                                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            lights_.push_back(
                vkt::create_host_buffer(gpu, lights_size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            frame_sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, frame_layout_));
            vkt::write_buffer_descriptor(device_, frame_sets_[i], 0,
                                         VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniforms_[i].buffer, 0,
                                         sizeof(FrameUniforms));
            vkt::write_buffer_descriptor(device_, frame_sets_[i], 1,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, lights_[i].buffer, 0,
                                         VK_WHOLE_SIZE);
        }
        gbuffer_set_ = vkt::allocate_descriptor_set(device_, pool_, gbuffer_layout_);
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
        sampler_ = vkt::Sampler(device_, handle);
    }

    void create_pipelines() {
        const VkPushConstantRange object_range{VK_SHADER_STAGE_VERTEX_BIT, 0,
                                               vkt::deferred::object_push_size};
        const VkDescriptorSetLayout scene_sets[] = {frame_layout_};
        scene_layout_ = vkt::create_pipeline_layout(device_, scene_sets, {&object_range, 1});
        const VkPushConstantRange lighting_range{VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                                 sizeof(LightingPush)};
        const VkDescriptorSetLayout lighting_sets[] = {frame_layout_, gbuffer_layout_};
        lighting_layout_ =
            vkt::create_pipeline_layout(device_, lighting_sets, {&lighting_range, 1});

        const std::string& chapter = chapter_;
        vkt::ShaderModule scene_vert = vkt::load_shader(device_, chapter, "scene.vert");
        vkt::ShaderModule gbuffer_frag = vkt::load_shader(device_, chapter, "gbuffer.frag");
        vkt::ShaderModule forward_frag = vkt::load_shader(device_, chapter, "forward.frag");
        vkt::ShaderModule fullscreen = vkt::load_shader(device_, chapter, "fullscreen.vert");
        vkt::ShaderModule lighting_frag = vkt::load_shader(device_, chapter, "lighting.frag");
        const VkVertexInputBindingDescription input{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, normal)},
        };
        // [pipelines]
        // The G-buffer pass: three colour attachments and depth, no blending.
        pipelines_.gbuffer = vkt::create_graphics_pipeline(
            device_, {.vertex = scene_vert,
                      .fragment = gbuffer_frag,
                      .layout = scene_layout_,
                      .bindings = {&input, 1},
                      .attributes = attributes,
                      .cull_mode = VK_CULL_MODE_BACK_BIT,
                      .color_formats = {std::begin(gbuffer_formats), std::end(gbuffer_formats)},
                      .depth_format = depth_format});
        // The lighting pass: no vertex input, no depth, one colour target.
        auto lighting = [&](VkFormat target) {
            return vkt::create_graphics_pipeline(device_, {.vertex = fullscreen,
                                                           .fragment = lighting_frag,
                                                           .layout = lighting_layout_,
                                                           .color_formats = {target}});
        };
        // [/pipelines]
        auto forward = [&](VkFormat target) {
            return vkt::create_graphics_pipeline(device_, {.vertex = scene_vert,
                                                           .fragment = forward_frag,
                                                           .layout = scene_layout_,
                                                           .bindings = {&input, 1},
                                                           .attributes = attributes,
                                                           .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                           .color_formats = {target},
                                                           .depth_format = depth_format});
        };
        pipelines_.lighting = lighting(colour_format_);
        pipelines_.forward = forward(colour_format_);
        if (!verify_.empty()) {
            pipelines_.verify_lighting = lighting(verify_format);
            pipelines_.verify_forward = forward(verify_format);
        }
    }

    // [update]
    void update(uint32_t slot, VkExtent2D extent, float t) {
        FrameUniforms frame{};
        frame.view = glm::lookAt(eye, glm::vec3(0.0f, 0.3f, 0.0f), glm::vec3(0, 1, 0));
        frame.proj = vkt::vulkan_perspective(
            glm::radians(45.0f), float(extent.width) / float(extent.height), 0.1f, 100.0f);
        frame.inverse_view_proj = glm::inverse(frame.proj * frame.view);
        frame.camera_position = eye;
        frame.light_count = light_count_;
        frame.ambient = glm::vec3(0.03f);
        frame.depth_view_far = 20.0f;
        const std::vector<vkt::deferred::Material> materials = make_materials();
        std::copy(materials.begin(), materials.end(), frame.materials);
        std::memcpy(uniforms_[slot].mapped, &frame, sizeof frame);
        uniform_copy_ = frame;
        lights_now_ = make_lights(light_count_, t);
        std::memcpy(lights_[slot].mapped, lights_now_.data(),
                    lights_now_.size() * sizeof(vkt::PointLight));
        objects_ = make_objects(t);
    }
    // [/update]

    // [barriers]
    // What one barrier waits for and what it allows, and the layout change.
    struct Transition {
        VkPipelineStageFlags2 src_stage;
        VkAccessFlags2 src_access;
        VkPipelineStageFlags2 dst_stage;
        VkAccessFlags2 dst_access;
        VkImageLayout old_layout, new_layout;
    };

    // One barrier for each G-buffer image, all four in one call.
    void transition_gbuffer(VkCommandBuffer cmd, const Transition& colour,
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

    static constexpr VkPipelineStageFlags2 fragment_tests =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

    // Before pass 1: the old contents are not needed (UNDEFINED), but the last
    // frame may still be using the images: its lighting pass reading them
    // (FRAGMENT_SHADER), its pass 1 writing them. Wait for both, then allow
    // attachment writes.
    void gbuffer_to_write(VkCommandBuffer cmd) const {
        transition_gbuffer(cmd,
                           {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
                           {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | fragment_tests,
                            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, fragment_tests,
                            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                            VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL});
    }

    // Between the passes: pass 1's attachment writes (colour output; depth,
    // stored by the fragment tests) must be finished and made visible to the
    // fragment shader of pass 2, and each image moves to a read-only layout.
    void gbuffer_to_read(VkCommandBuffer cmd) const {
        transition_gbuffer(
            cmd,
            {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
            {fragment_tests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
             VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
             VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL});
    }
    // [/barriers]

    void draw_objects(VkCommandBuffer cmd, uint32_t slot) const {
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_layout_, 0, 1,
                                &frame_sets_[slot], 0, nullptr);
        for (const Object& object : objects_) {
            const ObjectPush push = object_push(object);
            vkCmdPushConstants(cmd, scene_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0,
                               vkt::deferred::object_push_size, &push);
            const MeshRange& mesh = meshes_[object.mesh];
            vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, 0);
        }
    }

    // [gbuffer-pass]
    // Pass 1: dynamic rendering into three colour attachments and depth. Each
    // is cleared: where nothing is drawn, depth stays 1 and the lighting pass
    // shows the background there.
    void draw_gbuffer(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent) const {
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
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.gbuffer);
        draw_objects(cmd, slot);
        vkCmdEndRendering(cmd);
    }
    // [/gbuffer-pass]

    // [lighting-pass]
    // Pass 2: one full-screen triangle into the target; no vertex buffer, no
    // depth. Set 0 holds the lights, set 1 the G-buffer.
    void draw_lighting(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent, VkImageView target,
                       VkPipeline pipeline, const LightingPush& push) const {
        const VkRenderingAttachmentInfo colour{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = target,
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,  // every pixel is written
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
        };
        const VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .renderArea = {{0, 0}, extent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &colour,
        };
        vkCmdBeginRendering(cmd, &rendering);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        const VkDescriptorSet sets[] = {frame_sets_[slot], gbuffer_set_};
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lighting_layout_, 0, 2, sets,
                                0, nullptr);
        vkCmdPushConstants(cmd, lighting_layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                           &push);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    // [/lighting-pass]

    // The forward path: one pass, lit as drawn (depth already in
    // DEPTH_ATTACHMENT_OPTIMAL, by vkt::begin_depth_frame).
    void draw_forward(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent, VkImageView target,
                      VkPipeline pipeline) const {
        const VkRenderingAttachmentInfo colour{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = target,
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.02f, 0.02f, 0.04f, 1.0f}}},  // lighting.frag's background
        };
        const VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = forward_depth_.view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
            .clearValue = {.depthStencil = {1.0f, 0}},
        };
        const VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .renderArea = {{0, 0}, extent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &colour,
            .pDepthAttachment = &depth,
        };
        vkCmdBeginRendering(cmd, &rendering);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        draw_objects(cmd, slot);
        vkCmdEndRendering(cmd);
    }

    // [verify]
    // --verify: the checks of verify.hpp, on this frame. Lights n .. 2n - 1
    // of the buffer become the n lights lifted far out of reach.
    void verify(const vkt::Frame& frame) {
        const uint32_t n = light_count_, slot = frame.slot;
        std::vector<vkt::PointLight> lifted = lights_now_;
        for (vkt::PointLight& light : lifted) light.position.y += 1000.0f;
        std::memcpy(static_cast<vkt::PointLight*>(lights_[slot].mapped) + n, lifted.data(),
                    n * sizeof(vkt::PointLight));
        const VkExtent2D e = frame.extent;
        vkt::deferred::verify(
            verify_,
            {gpu_,
             e,
             {gbuffer_.base_colour.image, gbuffer_.normal.image, gbuffer_.material.image,
              gbuffer_.depth.image},
             uniform_copy_.inverse_view_proj,
             eye,
             uniform_copy_.ambient,
             lights_now_},
            {[&](VkCommandBuffer cmd) {
                 gbuffer_to_write(cmd);
                 draw_gbuffer(cmd, slot, e);
                 gbuffer_to_read(cmd);
             },
             [&](VkCommandBuffer cmd, VkImageView target, const LightingPush& push) {
                 draw_lighting(cmd, slot, e, target, pipelines_.verify_lighting, push);
             },
             [&](VkCommandBuffer cmd, VkImageView target) {
                 vkt::begin_depth_frame(cmd, forward_depth_.image);
                 draw_forward(cmd, slot, e, target, pipelines_.verify_forward);
             }});
    }
    // [/verify]

    vkt::Gpu gpu_;
    VkPhysicalDevice physical_;
    VkDevice device_;
    std::string chapter_;
    VkFormat colour_format_;
    uint32_t slots_;
    uint32_t max_storage_range_;
    bool forward_ = false;
    uint32_t light_count_ = 1;
    int32_t view_ = vkt::deferred::view_lit;
    std::string verify_;
    uint64_t verify_frame_ = 0;
    MeshRange meshes_[mesh_count];
    vkt::Buffer vertex_buffer_, index_buffer_;
    std::vector<vkt::Buffer> uniforms_, lights_;  // [slot]
    FrameUniforms uniform_copy_{};                // this frame's, for --verify
    std::vector<vkt::PointLight> lights_now_;     // this frame's
    std::vector<Object> objects_;                 // this frame's
    vkt::DescriptorSetLayout frame_layout_, gbuffer_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> frame_sets_;  // [slot]
    VkDescriptorSet gbuffer_set_ = VK_NULL_HANDLE;
    vkt::Sampler sampler_;
    vkt::PipelineLayout scene_layout_, lighting_layout_;
    struct {
        vkt::Pipeline gbuffer, lighting, forward, verify_lighting, verify_forward;
    } pipelines_;
    GBuffer gbuffer_;
    vkt::Image forward_depth_;
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "16_deferred", .title = "16 - deferred"};
    // DEPTH_ATTACHMENT_OPTIMAL and DEPTH_READ_ONLY_OPTIMAL (chapter 08).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        {.name = "--path",
         .type = vkt::OptionType::choice,
         .value_name = "PATH",
         .help = "deferred (G-buffer, then a lighting pass) or forward (lit as drawn)",
         .default_value = "deferred",
         .choices = {"deferred", "forward"}},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "lit, or one G-buffer target alone: albedo, normal, material, depth",
         .default_value = "lit",
         .choices = {"lit", "albedo", "normal", "material", "depth"}},
        {.name = "--lights",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many point lights, 1 to 65536 (2 MiB of lights per frame in flight)",
         .default_value = "32",
         .min = 1,
         .max = double(max_lights)},
        {.name = "--verify",
         .type = vkt::OptionType::choice,
         .value_name = "CHECK",
         .help = "check the last frame: cpu (against the CPU reference), additivity, forward",
         .choices = {"cpu", "additivity", "forward"}},
    };
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Deferred>(context);
    });
}
