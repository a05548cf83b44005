#pragma once
// Chapter 20's third way to draw the lines (--raster binned): the compute
// rasteriser of compute_raster.hpp, binned. Each object's box on the screen
// (the transform pass's, transform_boxes.comp) is cut into tiles small enough for one workgroup's
// shared memory (bin.comp: a count, a prefix sum, a scatter); one workgroup per tile draws the
// object's lines into shared memory and merges the tile into the image with one atomic per pixel
// reached (tiles.comp). It draws into ComputeRaster's pixel buffer with its palette (that pass's
// set 1) and owns set 2 of the chapter's layout (layouts.hpp): its own buffers.

#include "compute_raster.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/device.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>

namespace ch20 {

// [compute-barrier]
// One memory barrier for every buffer: the compute writes so far, visible to
// the next dispatch's reads and writes (and the next dispatch waits for every
// earlier one, the previous frame's included).
inline void compute_barrier(VkCommandBuffer cmd) {
    const VkMemoryBarrier2 barrier{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                   .srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                   .srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                   .dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                   .dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    const VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                      .memoryBarrierCount = 1,
                                      .pMemoryBarriers = &barrier};
    vkCmdPipelineBarrier2(cmd, &dependency);
}
// [/compute-barrier]

class BinnedRaster {
public:
    enum Binding : uint32_t { object_lines_binding, boxes_binding, tiles_binding, binding_count };

    // [subgroups]
    // The transform pass merges the boxes with subgroupMin and subgroupMax
    // (transform_boxes.comp). Vulkan 1.1 promises subgroups in compute
    // shaders, but of their operations only the basic ones; min and max are
    // "arithmetic", which nearly every device has, lavapipe included.
    static bool available(const vkt::Context& context) {
        VkPhysicalDeviceSubgroupProperties subgroups{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
        VkPhysicalDeviceProperties2 properties{
            .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, .pNext = &subgroups};
        vkGetPhysicalDeviceProperties2(context.physical, &properties);
        return (subgroups.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) &&
               (subgroups.supportedOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT) &&
               !context.hidden.hides("VK_SUBGROUP_FEATURE_ARITHMETIC_BIT");
    }
    static void check_device(const vkt::Context& context) {
        if (!available(context))
            throw vkt::Error(std::string("--raster binned needs subgroup arithmetic in compute "
                                         "shaders (VK_SUBGROUP_FEATURE_ARITHMETIC_BIT), which ") +
                             context.properties.deviceName + " lacks: use --raster compute");
    }
    // [/subgroups]

    // [binned-setup]
    // Built once: each object's first line and line count (line_counts:
    // each object's, in the order of the index buffer), and its box, which
    // the boxes pass writes each frame. The tiles are as large as shared
    // memory allows (88x88 pixels in 32 KiB, 104x104 in 48 KiB), so that
    // one holds a small object whole; the tuning says how many invocations
    // share out an object's lines (tuning.hpp).
    BinnedRaster(const vkt::Context& context, const Tuning& tuning, const Layouts& layouts,
                 std::span<const uint32_t> line_counts)
        : gpu_(context.gpu()),
          device_(context.device),
          layout_(layouts.pipeline),
          object_count_(uint32_t(line_counts.size())) {
        std::vector<uint32_t> lines;  // (first, count) per object
        uint32_t first = 0;
        for (uint32_t count : line_counts) {
            lines.insert(lines.end(), {first, count});
            first += count;
        }
        object_lines_ = vkt::create_device_buffer(gpu_, lines.data(), lines.size() * 4,
                                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        boxes_ = vkt::create_buffer(
            context.physical, device_, VkDeviceSize(object_count_) * 16,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        pool_ = storage_pool(device_, 1, binding_count);
        set_ = vkt::allocate_descriptor_set(device_, pool_, layouts.bins);
        vkt::write_buffer_descriptor(device_, set_, object_lines_binding,
                                     VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, object_lines_.buffer, 0,
                                     VK_WHOLE_SIZE);
        vkt::write_buffer_descriptor(device_, set_, boxes_binding,
                                     VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, boxes_.buffer, 0,
                                     VK_WHOLE_SIZE);
        const VkPhysicalDeviceLimits& limits = context.properties.limits;
        piece_ = uint32_t(std::sqrt(double(limits.maxComputeSharedMemorySize) / 4)) / 8 * 8;
        struct Constants {
            uint32_t piece, group;
        };
        const Constants constants{piece_, tuning.tile_group};
        const VkSpecializationMapEntry entries[] = {
            {0, offsetof(Constants, piece), sizeof(Constants::piece)},
            {1, offsetof(Constants, group), sizeof(Constants::group)}};
        // bin.comp takes only the piece; tiles.comp the piece and the group.
        const VkSpecializationInfo piece{1, entries, sizeof(Constants::piece), &constants};
        const VkSpecializationInfo piece_and_group{2, entries, sizeof(Constants), &constants};
        const auto load = [&](const char* name, const VkSpecializationInfo* specialization) {
            vkt::ShaderModule shader = vkt::load_shader(device_, context.chapter, name);
            return vkt::create_compute_pipeline(device_, shader, layout_, specialization);
        };
        bin_ = load("bin.comp", &piece);
        tiles_pass_ = load("tiles.comp", &piece_and_group);
        resize(context.extent);
    }
    // [/binned-setup]

    // [work-list]
    // The tile pass's dispatch and count, then an (object, piece) pair per
    // tile: room for every object to cover the whole image.
    void resize(VkExtent2D extent) {
        const VkDeviceSize per_object =
            vkt::dispatch_count(extent.width, piece_) * vkt::dispatch_count(extent.height, piece_);
        tiles_ = vkt::create_buffer(
            gpu_.physical, device_, 16 + 8 * per_object * object_count_,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
            VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        vkt::write_buffer_descriptor(device_, set_, tiles_binding,
                                     VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, tiles_.buffer, 0,
                                     VK_WHOLE_SIZE);
    }
    // [/work-list]

    // [binned-record]
    // Before the transform pass: set 2 bound for it and the passes after,
    // and the boxes from zeros (after the previous frame's passes have read
    // them), for its atomicMax to grow.
    void clear_boxes(VkCommandBuffer cmd) const {
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 2, 1, &set_, 0,
                                nullptr);
        vkt::buffer_barrier(cmd, boxes_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdFillBuffer(cmd, boxes_.buffer, 0, VK_WHOLE_SIZE, 0);
        vkt::buffer_barrier(
            cmd, boxes_.buffer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    }

    // After it: the work list from the boxes (once the previous frame's
    // indirect dispatch has read the list). Sets 0 and 2 and the push
    // constants are bound already.
    void bin(VkCommandBuffer cmd) const {
        compute_barrier(cmd);  // the transform pass's boxes
        vkt::buffer_barrier(cmd, tiles_.buffer, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bin_);
        vkCmdDispatch(cmd, 1, 1, 1);
    }

    // The image filled with the background (ComputeRaster's clear: a fill,
    // or none after the last frame's resolve), then one workgroup per tile,
    // as many as bin.comp wrote into the dispatch.
    void draw(VkCommandBuffer cmd, ComputeRaster& raster, vkt::GpuTimer* timer = nullptr,
              uint32_t slot = 0) const {
        raster.clear(cmd, timer, slot);
        compute_barrier(cmd);
        vkt::buffer_barrier(cmd, tiles_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
        vkt::GpuScope scope(timer, cmd, slot, "tiles");
        raster.bind_set(cmd);  // the ends, the pixels, the palette
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, tiles_pass_);
        vkCmdDispatchIndirect(cmd, tiles_.buffer, 0);
    }
    // [/binned-record]

    // [verify-raster]
    // --verify raster: the frame drawn by both compute rasterisers, one after
    // the other into the same pixel buffer, each copied out; then every word
    // compared. `transform` records the pose and transform passes (and clears
    // the boxes, binding set 2, between them).
    void verify(ComputeRaster& simple, VkExtent2D extent, VkBuffer projected,
                const std::function<void(VkCommandBuffer)>& transform) const {
        const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
        vkt::Buffer a = vkt::create_host_buffer(gpu_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        vkt::Buffer b = vkt::create_host_buffer(gpu_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        const auto copy_out = [&](VkCommandBuffer cmd, VkBuffer host) {
            vkt::buffer_barrier(cmd, simple.pixels(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy region{0, 0, bytes};
            vkCmdCopyBuffer(cmd, simple.pixels(), host, 1, &region);
            vkt::buffer_barrier(cmd, host, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                VK_ACCESS_2_HOST_READ_BIT);
        };
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            transform(cmd);
            simple.draw(cmd, projected);
            copy_out(cmd, a.buffer);
            bin(cmd);
            draw(cmd, simple);
            copy_out(cmd, b.buffer);
        });
        const auto* simple_words = static_cast<const uint32_t*>(a.mapped);
        const auto* binned_words = static_cast<const uint32_t*>(b.mapped);
        size_t differ = 0, lit = 0, first = 0;
        for (size_t i = 0; i < bytes / 4; ++i) {
            if (simple_words[i] >> 24 != 0) ++lit;
            if (simple_words[i] != binned_words[i] && differ++ == 0) first = i;
        }
        std::fprintf(stderr,
                     "20_ndim_compute: verify: binned against compute, %ux%u pixels (%zu lit by "
                     "lines), %zu differ\n",
                     extent.width, extent.height, lit, differ);
        if (differ != 0)
            throw vkt::Error(
                "verify: the binned rasteriser's pixel (" + std::to_string(first % extent.width) +
                ", " + std::to_string(first / extent.width) + ") differs from the compute one's");
    }
    // [/verify-raster]

private:
    vkt::Gpu gpu_;
    VkDevice device_;
    VkPipelineLayout layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;  // set 2
    uint32_t object_count_ = 0;
    uint32_t piece_ = 64;  // the shaders' PIECE: a tile's largest side
    vkt::Buffer object_lines_, boxes_, tiles_;
    vkt::Pipeline bin_, tiles_pass_;
};

}  // namespace ch20
