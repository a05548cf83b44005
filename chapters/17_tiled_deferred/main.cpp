// Chapter 17: tiled deferred shading.
//
// Chapter 16's scene and G-buffer, under thousands of moving point lights.
// Chapter 16's lighting pass tests every light at every pixel; here a compute
// pass first cuts the screen into 16 x 16 pixel tiles, finds each tile's depth
// range, and keeps for each tile only the lights whose spheres may touch the
// tile's small frustum. The lighting then loops over its tile's list alone:
//
//   --shade fragment: the compute pass writes the lists to a buffer and a
//                     full-screen triangle lights the pixels (three passes);
//   --shade compute:  one dispatch culls and lights, the list never leaving
//                     shared memory; the result is copied to the target.
//
// --view heat shows how many lights each tile kept. --verify brute compares
// both tiled results with chapter 16's brute-force lighting pass.

#include "gbuffer_pass.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/scene/deferred_verify.hpp"
#include "vkt/scene/tiles.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

using vkt::deferred::FrameUniforms;

constexpr uint32_t max_lights = 65536;  // as chapter 16: 2 MiB of lights per frame in flight
// [limits]
constexpr uint32_t tile_size = 16;          // TILE_SIZE in tiles.glsl
constexpr uint32_t max_tile_lights = 1024;  // MAX_TILE_LIGHTS: 4 KiB per tile
// [/limits]
constexpr VkFormat shaded_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // --shade compute writes it
// --verify renders into float targets, so that nothing is clamped or rounded.
constexpr VkFormat verify_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr int32_t view_lit = 0, view_heat = 5;  // VIEW_LIT, VIEW_HEAT
const glm::vec3 eye(0.0f, 6.0f, 10.0f);

struct TileStats {  // TileStats in tiles.comp
    uint32_t overflowed_tiles, most_lights, total_lights, lit_tiles;
};

class TiledDeferred : public vkt::Renderer {
public:
    explicit TiledDeferred(const vkt::Context& context)
        : gpu_(context.gpu()),
          device_(context.device),
          slots_(context.frames_in_flight),
          limits_(context.properties.limits),
          colour_format_(context.color_format) {
        const vkt::Options& options = context.options;
        compute_ = options.text("--shade") == "compute";
        view_ = options.text("--view") == "heat" ? view_heat : view_lit;
        light_count_ = uint32_t(options.integer("--lights"));
        verify_ = options.has("--verify");
        verify_frame_ = options.frames.value_or(1) - 1;
        std::fprintf(stderr, "17_tiled_deferred: %u light%s, shade %s, view %s\n", light_count_,
                     light_count_ == 1 ? "" : "s", compute_ ? "compute" : "fragment",
                     options.text("--view").c_str());
        // A workgroup is a tile: 256 invocations, more than the 128 promised.
        if (limits_.maxComputeWorkGroupInvocations < tile_size * tile_size)
            throw vkt::Error("this device runs at most " +
                             std::to_string(limits_.maxComputeWorkGroupInvocations) +
                             " invocations per workgroup; a 16 x 16 tile needs 256");
        check_blit(context.physical, context.color_format);
        create_descriptors();
        gbuffer_.emplace(context, frame_layout_);
        create_pipelines();
        resize(context.extent);
    }

    ~TiledDeferred() override {
        for (uint32_t slot = 0; slot < slots_; ++slot) read_stats(slot);
        if (tiles_seen_ > 0)
            std::fprintf(stderr,
                         "17_tiled_deferred: lights per lit tile: mean %.1f, most %u (a list "
                         "holds %u); tiles overflowed: %u\n",
                         double(lights_seen_) / double(tiles_seen_), most_lights_, max_tile_lights,
                         overflowed_);
    }

    // Everything as large as the screen: the G-buffer, the tiles' lists, the
    // compute path's output; set 1 points at them.
    void resize(VkExtent2D extent) override {
        gbuffer_->resize(extent);
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        const VkDeviceSize list_bytes = VkDeviceSize{grid.count()} * max_tile_lights * 4;
        if (list_bytes > limits_.maxStorageBufferRange)
            throw vkt::Error(std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                             " needs " + std::to_string(list_bytes >> 20) +
                             " MiB of light lists, more than this device's "
                             "maxStorageBufferRange");
        const VkPhysicalDevice physical = gpu_.physical;
        const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        const auto local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        tile_counts_ = vkt::create_buffer(physical, device_, grid.count() * 4, storage, local);
        tile_lights_ = vkt::create_buffer(physical, device_, list_bytes, storage, local);
        shaded_ = vkt::create_image_2d(physical, device_, shaded_format, extent,
                                       VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                       VK_IMAGE_ASPECT_COLOR_BIT);
        // It stays in GENERAL, the layout storage images need (blits and
        // copies read GENERAL too), from here on.
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE);
        });
        for (uint32_t binding = 0; binding < 4; ++binding)
            vkt::write_image_descriptor(device_, screen_set_, binding,
                                        gbuffer_->images[binding].view, sampler_,
                                        ch17::GBufferPass::read_layout(int(binding)));
        vkt::write_buffer_descriptor(device_, screen_set_, 4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     tile_counts_.buffer, 0, VK_WHOLE_SIZE);
        vkt::write_buffer_descriptor(device_, screen_set_, 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     tile_lights_.buffer, 0, VK_WHOLE_SIZE);
        const VkDescriptorImageInfo image{VK_NULL_HANDLE, shaded_.view, VK_IMAGE_LAYOUT_GENERAL};
        const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                         .dstSet = screen_set_,
                                         .dstBinding = 6,
                                         .descriptorCount = 1,
                                         .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                         .pImageInfo = &image};
        vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
    }

    // [frame]
    void record(const vkt::Frame& frame) override {
        read_stats(frame.slot);  // the last use of this slot is finished
        update(frame.slot, frame.extent, float(frame.time));
        if (verify_ && frame.index == verify_frame_) verify(frame.slot, frame.extent);
        const VkCommandBuffer cmd = frame.cmd;
        {
            auto scope = frame.gpu_scope("gbuffer");
            gbuffer_->record(cmd, frame_sets_[frame.slot], frame.extent, objects_);
        }
        if (compute_) {
            {
                auto scope = frame.gpu_scope("shade");  // cull and shade, one dispatch
                shade_compute(cmd, frame.slot, frame.extent, view_);
            }
            auto scope = frame.gpu_scope("copy");
            copy_to_target(cmd, frame.target, frame.extent);
        } else {
            {
                auto scope = frame.gpu_scope("cull");
                cull(cmd, frame.slot, frame.extent);
            }
            auto scope = frame.gpu_scope("lighting");
            draw_lighting(cmd, frame.slot, frame.extent, frame.target_view, pipelines_.lighting,
                          &view_, sizeof view_);
        }
    }
    // [/frame]

private:
    // --shade compute copies a float image to the _SRGB target with a blit,
    // which converts (and encodes sRGB) on the way.
    static void check_blit(VkPhysicalDevice physical, VkFormat target) {
        VkFormatProperties source{}, destination{};
        vkGetPhysicalDeviceFormatProperties(physical, shaded_format, &source);
        vkGetPhysicalDeviceFormatProperties(physical, target, &destination);
        if (!(source.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT) ||
            !(source.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT) ||
            !(destination.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
            throw vkt::Error(
                "this device cannot blit R32G32B32A32_SFLOAT storage images "
                "to the target");
    }

    // Set 0, one per frame in flight: uniforms, lights, tile statistics.
    // Set 1, one for all: the G-buffer, the tiles' lists, the compute output.
    void create_descriptors() {
        const VkShaderStageFlags all =
            VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
        const VkDescriptorSetLayoutBinding frame_bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, all, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, all, nullptr},
            {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        };
        frame_layout_ = vkt::create_descriptor_set_layout(device_, frame_bindings);
        const VkShaderStageFlags readers =
            VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
        std::vector<VkDescriptorSetLayoutBinding> screen_bindings;
        for (uint32_t binding = 0; binding < 4; ++binding)
            screen_bindings.push_back(
                {binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, readers, nullptr});
        screen_bindings.push_back({4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, readers, nullptr});
        screen_bindings.push_back({5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, readers, nullptr});
        screen_bindings.push_back(
            {6, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        screen_layout_ = vkt::create_descriptor_set_layout(device_, screen_bindings);

        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slots_},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * slots_ + 2},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
        pool_ = vkt::create_descriptor_pool(device_, slots_ + 1, sizes);
        const VkDeviceSize lights_size = VkDeviceSize{light_count_} * sizeof(vkt::PointLight);
        if (lights_size > limits_.maxStorageBufferRange)
            throw vkt::Error("--lights " + std::to_string(light_count_) +
                             ": more than this device's maxStorageBufferRange allows");
        for (uint32_t i = 0; i < slots_; ++i) {
            uniforms_.push_back(vkt::create_host_buffer(gpu_, sizeof(FrameUniforms),
                                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            lights_.push_back(
                vkt::create_host_buffer(gpu_, lights_size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            stats_.push_back(vkt::create_host_buffer(gpu_, sizeof(TileStats),
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            std::memset(stats_[i].mapped, 0, sizeof(TileStats));
            stats_pending_.push_back(false);
            frame_sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, frame_layout_));
            const vkt::Buffer* buffers[] = {&uniforms_[i], &lights_[i], &stats_[i]};
            for (uint32_t b = 0; b < 3; ++b)
                vkt::write_buffer_descriptor(
                    device_, frame_sets_[i], b,
                    b == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                    buffers[b]->buffer, 0, VK_WHOLE_SIZE);
        }
        screen_set_ = vkt::allocate_descriptor_set(device_, pool_, screen_layout_);
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
        // One layout for every pass after the G-buffer: sets 0 and 1, and 16
        // bytes of push constants (chapter 16's LightingPush is the largest).
        const VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                                        0, sizeof(vkt::deferred::LightingPush)};
        const VkDescriptorSetLayout sets[] = {frame_layout_, screen_layout_};
        layout_ = vkt::create_pipeline_layout(device_, sets, {&range, 1});
        // [pipelines]
        // tiles.comp twice: SHADE false writes the lists, SHADE true shades.
        vkt::ShaderModule tiles = vkt::load_shader(device_, "17_tiled_deferred", "tiles.comp");
        for (const VkBool32 shade : {VK_FALSE, VK_TRUE}) {
            const VkSpecializationMapEntry entry{0, 0, sizeof(VkBool32)};
            const VkSpecializationInfo specialization{1, &entry, sizeof shade, &shade};
            (shade ? pipelines_.shade : pipelines_.cull) =
                vkt::create_compute_pipeline(device_, tiles, layout_, &specialization);
        }
        // [/pipelines]
        vkt::ShaderModule fullscreen =
            vkt::load_shader(device_, "17_tiled_deferred", "fullscreen.vert");
        vkt::ShaderModule tiled =
            vkt::load_shader(device_, "17_tiled_deferred", "tiled_lighting.frag");
        vkt::ShaderModule brute = vkt::load_shader(device_, "17_tiled_deferred", "lighting.frag");
        auto lighting = [&](VkShaderModule fragment, VkFormat target) {
            return vkt::create_graphics_pipeline(device_, {.vertex = fullscreen,
                                                           .fragment = fragment,
                                                           .layout = layout_,
                                                           .color_formats = {target}});
        };
        pipelines_.lighting = lighting(tiled, colour_format_);
        if (verify_) {  // float targets: nothing rounded or clamped
            pipelines_.verify_lighting = lighting(tiled, verify_format);
            pipelines_.verify_brute = lighting(brute, verify_format);
        }
    }

    // Chapter 16's frame: the same camera, materials, shapes and lights.
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
        const std::vector<vkt::deferred::Material> materials = vkt::deferred::make_materials();
        std::copy(materials.begin(), materials.end(), frame.materials);
        std::memcpy(uniforms_[slot].mapped, &frame, sizeof frame);
        lights_now_ = vkt::deferred::make_lights(light_count_, t);
        std::memcpy(lights_[slot].mapped, lights_now_.data(),
                    lights_now_.size() * sizeof(vkt::PointLight));
        objects_ = vkt::deferred::make_objects(t);
    }

    // What the slot's last frame counted (it is finished), then zeroed.
    void read_stats(uint32_t slot) {
        if (!stats_pending_[slot]) {
            stats_pending_[slot] = true;  // the coming frame will count
            return;
        }
        TileStats stats{};
        std::memcpy(&stats, stats_[slot].mapped, sizeof stats);
        std::memset(stats_[slot].mapped, 0, sizeof stats);
        overflowed_ = std::max(overflowed_, stats.overflowed_tiles);
        most_lights_ = std::max(most_lights_, stats.most_lights);
        lights_seen_ += stats.total_lights;
        tiles_seen_ += stats.lit_tiles;
    }

    void bind(VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipeline pipeline, uint32_t slot,
              const void* push, uint32_t push_size) const {
        vkCmdBindPipeline(cmd, point, pipeline);
        const VkDescriptorSet sets[] = {frame_sets_[slot], screen_set_};
        vkCmdBindDescriptorSets(cmd, point, layout_, 0, 2, sets, 0, nullptr);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                           0, push_size, push);
    }

    // [cull]
    // One workgroup per tile writes the tile's list. The buffers are shared by
    // the frames in flight: wait for the last frame's lighting pass to finish
    // reading them; afterwards, make the lists visible to this frame's.
    void cull(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent) const {
        tiles_to_write(cmd);
        bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.cull, slot, &view_, sizeof view_);
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        vkCmdDispatch(cmd, grid.x, grid.y, 1);
        const VkBuffer buffers[] = {tile_counts_.buffer, tile_lights_.buffer};
        for (VkBuffer buffer : buffers)
            vkt::buffer_barrier(cmd, buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
        stats_to_host(cmd, slot);
    }
    // [/cull]

    void tiles_to_write(VkCommandBuffer cmd) const {
        const VkBuffer buffers[] = {tile_counts_.buffer, tile_lights_.buffer};
        for (VkBuffer buffer : buffers)
            vkt::buffer_barrier(
                cmd, buffer,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }

    void stats_to_host(VkCommandBuffer cmd, uint32_t slot) const {
        vkt::buffer_barrier(cmd, stats_[slot].buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                            VK_ACCESS_2_HOST_READ_BIT);
    }

    // [lighting]
    // --shade fragment: one full-screen triangle, lit from the tiles' lists.
    void draw_lighting(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent, VkImageView target,
                       VkPipeline pipeline, const void* push, uint32_t push_size) const {
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
        bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline, slot, push, push_size);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    // [/lighting]

    // [shade-compute]
    // --shade compute: one dispatch culls and shades into the float image.
    // The image is shared by the frames in flight: wait for the last frame's
    // copy to have read it; afterwards, make the writes visible to the copy.
    void shade_compute(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent, int32_t view) const {
        vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                           VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        tiles_to_write(cmd);  // the same shader: it could write the lists
        bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.shade, slot, &view, sizeof view);
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        vkCmdDispatch(cmd, grid.x, grid.y, 1);
        vkt::image_barrier(
            cmd, shaded_.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
            VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
            VK_ACCESS_2_TRANSFER_READ_BIT);
        stats_to_host(cmd, slot);
    }

    // The blit converts the linear floats to the target's _SRGB format; the
    // target then goes back to COLOR_ATTACHMENT_OPTIMAL, as the runner wants,
    // and the float image to GENERAL, where every other use expects it.
    void copy_to_target(VkCommandBuffer cmd, VkImage target, VkExtent2D extent) const {
        vkt::image_barrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkOffset3D corner{int32_t(extent.width), int32_t(extent.height), 1};
        const VkImageBlit region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .srcOffsets = {{0, 0, 0}, corner},
                                 .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .dstOffsets = {{0, 0, 0}, corner}};
        vkCmdBlitImage(cmd, shaded_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
        vkt::image_barrier(
            cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE);
    }
    // [/shade-compute]

    // [verify]
    // --verify brute: this frame once more, into float images: chapter 16's
    // lighting pass over every light, the tiled fragment pass and the tiled
    // compute pass. All three are read back and compared.
    void verify(uint32_t slot, VkExtent2D e) {
        const VkPhysicalDevice physical = gpu_.physical;
        std::vector<vkt::Image> targets;  // brute force, tiled fragment
        std::vector<vkt::deferred::HostCopy> copies;
        for (int i = 0; i < 2; ++i) {
            targets.push_back(vkt::create_image_2d(
                physical, device_, verify_format, e,
                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                VK_IMAGE_ASPECT_COLOR_BIT));
            copies.push_back(
                vkt::deferred::make_host_copy(physical, device_, targets[i].image, e, 16));
        }
        copies.push_back(vkt::deferred::make_host_copy(physical, device_, shaded_.image, e, 16));
        const vkt::deferred::LightingPush everything{vkt::deferred::view_lit, 0, light_count_,
                                                     1.0f};
        const int32_t lit = view_lit;
        constexpr auto colour_out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        std::memset(stats_[slot].mapped, 0, sizeof(TileStats));
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            for (const vkt::Image& target : targets)
                vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_UNDEFINED,
                                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, colour_out,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
            gbuffer_->record(cmd, frame_sets_[slot], e, objects_);
            draw_lighting(cmd, slot, e, targets[0].view, pipelines_.verify_brute, &everything,
                          sizeof everything);
            cull(cmd, slot, e);
            draw_lighting(cmd, slot, e, targets[1].view, pipelines_.verify_lighting, &lit,
                          sizeof lit);
            shade_compute(cmd, slot, e, lit);
            for (const vkt::Image& target : targets)
                vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colour_out,
                                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                   VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
            vkt::deferred::record_host_copies(cmd, e, copies);
            vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                               VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_NONE);
        });
        TileStats stats{};
        std::memcpy(&stats, stats_[slot].mapped, sizeof stats);
        std::memset(stats_[slot].mapped, 0, sizeof stats);
        const auto brute = vkt::deferred::host_colours(copies[0]),
                   fragment = vkt::deferred::host_colours(copies[1]),
                   compute = vkt::deferred::host_colours(copies[2]);
        const struct {
            const char* what;
            float difference;
        } results[] = {
            {"tiled fragment vs brute force",
             vkt::deferred::max_linear_difference(fragment, brute)},
            {"tiled compute vs brute force", vkt::deferred::max_linear_difference(compute, brute)},
            {"tiled fragment vs tiled compute",
             vkt::deferred::max_linear_difference(fragment, compute)},
        };
        constexpr float tolerance = 1e-4f;
        for (const auto& r : results)
            std::fprintf(stderr,
                         "17_tiled_deferred: verify brute: %s, largest difference %g "
                         "(tolerance %g), %ux%u pixels, %u lights\n",
                         r.what, r.difference, tolerance, e.width, e.height, light_count_);
        std::fprintf(stderr,
                     "17_tiled_deferred: verify brute: the most lights in a tile %u, "
                     "tiles overflowed %u\n",
                     stats.most_lights, stats.overflowed_tiles);
        if (stats.overflowed_tiles != 0)
            throw vkt::Error("--verify brute: " + std::to_string(stats.overflowed_tiles) +
                             " tiles had more than " + std::to_string(max_tile_lights) +
                             " lights; their lists dropped lights");
        for (const auto& r : results)
            if (!(r.difference <= tolerance))
                throw vkt::Error(std::string("--verify brute: ") + r.what + " differ by " +
                                 std::to_string(r.difference) + ", above " +
                                 std::to_string(tolerance));
    }
    // [/verify]

    vkt::Gpu gpu_;
    VkDevice device_;
    uint32_t slots_;
    VkPhysicalDeviceLimits limits_;
    VkFormat colour_format_;
    bool compute_ = false, verify_ = false;
    int32_t view_ = view_lit;
    uint32_t light_count_ = 1;
    uint64_t verify_frame_ = 0;
    std::vector<vkt::Buffer> uniforms_, lights_, stats_;  // [slot]
    std::vector<bool> stats_pending_;                     // [slot]
    uint32_t overflowed_ = 0, most_lights_ = 0;           // over the run
    uint64_t lights_seen_ = 0, tiles_seen_ = 0;
    std::vector<vkt::PointLight> lights_now_;
    std::vector<vkt::deferred::Object> objects_;
    vkt::DescriptorSetLayout frame_layout_, screen_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> frame_sets_;  // [slot]
    VkDescriptorSet screen_set_ = VK_NULL_HANDLE;
    vkt::Sampler sampler_;
    std::optional<ch17::GBufferPass> gbuffer_;
    vkt::Buffer tile_counts_, tile_lights_;
    vkt::Image shaded_;
    vkt::PipelineLayout layout_;
    struct {
        vkt::Pipeline cull, shade, lighting, verify_lighting, verify_brute;
    } pipelines_;
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "17_tiled_deferred", .title = "17 - tiled deferred"};
    // DEPTH_ATTACHMENT_OPTIMAL and DEPTH_READ_ONLY_OPTIMAL, as chapter 16; and
    // maintenance4, as chapter 13: glslang writes a compute shader's workgroup
    // size for Vulkan 1.3 as LocalSizeId, which needs it.
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts),
                                  VKT_FEATURE_13(maintenance4)};
    spec.options = {
        {.name = "--shade",
         .type = vkt::OptionType::choice,
         .value_name = "PASS",
         .help = "fragment (a compute pass writes light lists, a fragment pass lights) or "
                 "compute (one dispatch culls and lights)",
         .default_value = "fragment",
         .choices = {"fragment", "compute"}},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "lit, or heat: the number of lights each tile kept",
         .default_value = "lit",
         .choices = {"lit", "heat"}},
        {.name = "--lights",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many point lights, 1 to 65536 (as chapter 16)",
         .default_value = "1024",
         .min = 1,
         .max = double(max_lights)},
        {.name = "--verify",
         .type = vkt::OptionType::choice,
         .value_name = "CHECK",
         .help = "brute: compare both tiled paths with brute-force lighting on the last frame",
         .choices = {"brute"}},
    };
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<TiledDeferred>(context);
    });
}
