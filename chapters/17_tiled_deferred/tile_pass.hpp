#pragma once
// Chapter 17's tile pass, in compute: tiles.comp cuts the screen into 16 x 16
// pixel tiles and keeps, for each tile, the lights that may touch it. With
// --shade fragment it writes each tile's list for the lighting pass (cull);
// with --shade compute it lights the tile's pixels itself, into a float image
// that is then blitted to the target (shade, copy_to_target). Each tests
// every light (--cull tiled) or its tile's bin (--cull binned, bin_pass.hpp).

#include "vkt/core/barrier.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/tiles.hpp"

#include <string>

namespace ch17 {

// [limits]
constexpr uint32_t tile_size = 16;          // TILE_SIZE in tiles.glsl
constexpr uint32_t max_tile_lights = 2048;  // MAX_TILE_LIGHTS: 8 KiB per tile
// [/limits]
constexpr VkFormat shaded_format = VK_FORMAT_R32G32B32A32_SFLOAT;  // --shade compute writes it

struct TileStats {  // TileStats in tiles.glsl
    uint32_t overflowed_tiles, most_lights, total_lights, lit_tiles;
    uint32_t binned_entries, binned_budget, most_candidates;  // --cull binned
};

// Every pass after the G-buffer binds the same two sets through one pipeline
// layout: set 0, the frame's (uniforms, lights, tile statistics); set 1, the
// screen's (the G-buffer, the tiles' lists, the compute path's image).
struct PassSets {
    VkPipelineLayout layout;
    VkDescriptorSet frame_set, screen_set;
    VkBuffer stats;  // the frame's TileStats

    void bind(VkCommandBuffer cmd, VkPipelineBindPoint point, VkPipeline pipeline, const void* push,
              uint32_t push_size) const {
        vkCmdBindPipeline(cmd, point, pipeline);
        const VkDescriptorSet sets[] = {frame_set, screen_set};
        vkCmdBindDescriptorSets(cmd, point, layout, 0, 2, sets, 0, nullptr);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                           0, push_size, push);
    }
};

class TilePass {
public:
    TilePass(const vkt::Context& context, VkPipelineLayout layout)
        : gpu_(context.gpu()), limits_(context.properties.limits) {
        // A workgroup is a tile: 256 invocations, more than the 128 promised.
        if (limits_.maxComputeWorkGroupInvocations < tile_size * tile_size)
            throw vkt::Error("this device runs at most " +
                             std::to_string(limits_.maxComputeWorkGroupInvocations) +
                             " invocations per workgroup; a 16 x 16 tile needs 256");
        check_blit(context.physical, context.color_format);
        const VkDevice device = gpu_.device;
        // [pipelines]
        // tiles.comp four times: SHADE false writes the lists, SHADE true
        // shades; BINNED false tests every light, BINNED true the tile's bin.
        vkt::ShaderModule tiles = vkt::load_shader(device, context.chapter, "tiles.comp");
        for (const VkBool32 binned : {VK_FALSE, VK_TRUE})
            for (const VkBool32 shade : {VK_FALSE, VK_TRUE}) {
                const VkBool32 constants[] = {shade, binned};
                // constant_id 0 at constants[0], 1 at constants[1]: byte offsets.
                const VkSpecializationMapEntry entries[] = {
                    {0, 0, sizeof(VkBool32)}, {1, sizeof(VkBool32), sizeof(VkBool32)}};
                const VkSpecializationInfo specialization{2, entries, sizeof constants, constants};
                (shade ? shade_ : cull_)[binned] =
                    vkt::create_compute_pipeline(device, tiles, layout, &specialization);
            }
        // [/pipelines]
    }

    // The tiles' lists and the compute path's image are as large as the screen.
    void resize(VkExtent2D extent) {
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        const VkDeviceSize list_bytes = VkDeviceSize{grid.count()} * max_tile_lights * 4;
        if (list_bytes > limits_.maxStorageBufferRange)
            throw vkt::Error(std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                             " needs " + std::to_string(list_bytes >> 20) +
                             " MiB of light lists, more than this device's "
                             "maxStorageBufferRange");
        const VkPhysicalDevice physical = gpu_.physical;
        const VkDevice device = gpu_.device;
        // (TRANSFER_SRC: --verify bins copies them to the host.)
        const auto storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        const auto local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        counts_ =
            vkt::create_buffer(physical, device, VkDeviceSize{grid.count()} * 4, storage, local);
        lists_ = vkt::create_buffer(physical, device, list_bytes, storage, local);
        shaded_ = vkt::create_image_2d(physical, device, shaded_format, extent,
                                       VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                       VK_IMAGE_ASPECT_COLOR_BIT);
        // It stays in GENERAL, the layout storage images need (blits and
        // copies read GENERAL too), from here on.
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE);
        });
    }

    // Bindings 4 and 5 of set 1: the tiles' light counts and lists; 6: the image.
    void write_descriptors(VkDescriptorSet screen_set) const {
        const VkDevice device = gpu_.device;
        vkt::write_buffer_descriptor(device, screen_set, 4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     counts_.buffer, 0, VK_WHOLE_SIZE);
        vkt::write_buffer_descriptor(device, screen_set, 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     lists_.buffer, 0, VK_WHOLE_SIZE);
        vkt::write_storage_image_descriptor(device, screen_set, 6, shaded_.view);
    }

    VkImage shaded() const { return shaded_.image; }
    // The tiles' counts and lists, for --verify bins to read back.
    VkBuffer counts() const { return counts_.buffer; }
    VkBuffer lists() const { return lists_.buffer; }

    // [cull]
    // One workgroup per tile writes the tile's list. The buffers are shared by
    // the frames in flight: wait for the last frame's lighting pass to finish
    // reading them; afterwards, make the lists visible to this frame's (a
    // fragment pass, or with --shade lists a compute pass).
    void cull(VkCommandBuffer cmd, const PassSets& sets, VkExtent2D extent, int32_t view,
              bool binned) const {
        tiles_to_write(cmd);
        sets.bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, cull_[binned], &view, sizeof view);
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        vkCmdDispatch(cmd, grid.x, grid.y, 1);
        const VkBuffer buffers[] = {counts_.buffer, lists_.buffer};
        for (VkBuffer buffer : buffers)
            vkt::buffer_barrier(
                cmd, buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
        stats_to_host(cmd, sets.stats);
    }
    // [/cull]

    // [shade-compute]
    // --shade compute: one dispatch culls and shades into the float image.
    // The image is shared by the frames in flight: wait for the last frame's
    // copy to have read it; afterwards, make the writes visible to the copy.
    void shade(VkCommandBuffer cmd, const PassSets& sets, VkExtent2D extent, int32_t view,
               bool binned) const {
        image_to_write(cmd);
        tiles_to_write(cmd);  // the same shader: it could write the lists
        sets.bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, shade_[binned], &view, sizeof view);
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        vkCmdDispatch(cmd, grid.x, grid.y, 1);
        image_to_copy(cmd);
        stats_to_host(cmd, sets.stats);
    }

    // Before a dispatch writes the float image, and after (also --shade lists').
    void image_to_write(VkCommandBuffer cmd) const {
        vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                           VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    void image_to_copy(VkCommandBuffer cmd) const {
        vkt::image_barrier(
            cmd, shaded_.image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
            VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
            VK_ACCESS_2_TRANSFER_READ_BIT);
    }

    // The blit converts the linear floats to the target's _SRGB format. The
    // target comes untouched (from the stage `ready`, Frame::target_ready)
    // and stays in TRANSFER_DST_OPTIMAL, where the runner's next barrier
    // starts; the float image goes back to GENERAL, where every other use
    // expects it.
    void copy_to_target(VkCommandBuffer cmd, VkImage target, VkExtent2D extent,
                        VkPipelineStageFlags2 ready) const {
        vkt::image_barrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, ready, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkOffset3D corner{int32_t(extent.width), int32_t(extent.height), 1};
        const VkImageBlit region{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .srcOffsets = {{0, 0, 0}, corner},
                                 .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .dstOffsets = {{0, 0, 0}, corner}};
        vkCmdBlitImage(cmd, shaded_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
        vkt::image_barrier(cmd, shaded_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE);
    }
    // [/shade-compute]

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

    // [tiles-to-write]
    // Before a dispatch writes the lists: the last frame's lighting (a
    // fragment pass, or --shade lists' compute pass) must have finished
    // reading them, a write after a read; the source access also orders
    // these writes after the last frame's cull wrote them.
    void tiles_to_write(VkCommandBuffer cmd) const {
        const VkBuffer buffers[] = {counts_.buffer, lists_.buffer};
        for (VkBuffer buffer : buffers)
            vkt::buffer_barrier(
                cmd, buffer,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }
    // [/tiles-to-write]

    static void stats_to_host(VkCommandBuffer cmd, VkBuffer stats) {
        vkt::buffer_barrier(cmd, stats, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                            VK_ACCESS_2_HOST_READ_BIT);
    }

    vkt::Gpu gpu_;
    VkPhysicalDeviceLimits limits_;
    vkt::Pipeline cull_[2], shade_[2];  // [binned]
    vkt::Buffer counts_, lists_;        // the tiles' light counts and lists
    vkt::Image shaded_;                 // --shade compute's output, in GENERAL
};

}  // namespace ch17
