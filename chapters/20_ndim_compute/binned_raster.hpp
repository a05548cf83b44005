#pragma once
// Chapter 20's third way to draw the lines (--raster binned): the compute
// rasteriser of compute_raster.hpp with its lines sorted into screen tiles
// first, so that each workgroup draws one tile in shared memory and writes it
// once. Three passes: bounds.comp (a box of pixels per chunk of 64 lines and
// per object), bin.comp (each tile's list of objects: a count, a prefix sum,
// a scatter) and tiles.comp (each tile drawn), then ComputeRaster's copy to
// the target. It draws into ComputeRaster's pixel buffer with its palette
// (bindings 5 and 6) and keeps its own buffers in bindings 7 to 11.

#include "compute_raster.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>

namespace ch20 {

// The C++ side of bins.glsl's LineRange.
struct LineRange {
    uint32_t first_line, line_count, first_chunk, chunk_count;
};
constexpr uint32_t chunk = 64;  // lines per chunk (bins.glsl's CHUNK)

// One memory barrier for every buffer: the compute writes so far, visible to
// the next dispatch's reads and writes (and the next dispatch waits for every
// earlier one, which orders it after the previous frame's tile pass too).
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

class BinnedRaster {
public:
    // [binned-setup]
    // Built once: each object's lines as chunks of 64 (line_counts: each
    // object's, in the order of the index buffer), a box per chunk and per
    // object, written by the bounds pass each frame. The tile size and the
    // tile pass's workgroup size suit the device: a GPU wants many
    // invocations (small tiles, 256 invocations each), a CPU device few
    // workgroups with little to share out (64x64 tiles, 16 KiB of shared
    // memory, 64 invocations).
    BinnedRaster(const vkt::Context& context, VkPipelineLayout layout,
                 std::span<const VkDescriptorSet> sets, std::span<const uint32_t> line_counts,
                 uint32_t background)
        : gpu_(context.gpu()),
          device_(context.device),
          object_count_(uint32_t(line_counts.size())) {
        std::vector<LineRange> ranges;
        uint32_t first_line = 0, first_chunk = 0;
        for (uint32_t count : line_counts) {
            const auto chunks = uint32_t(vkt::dispatch_count(count, chunk));
            ranges.push_back({first_line, count, first_chunk, chunks});
            first_line += count;
            first_chunk += chunks;
            max_chunks_ = std::max(max_chunks_, chunks);
        }
        ranges_ = vkt::create_device_buffer(gpu_, ranges.data(), ranges.size() * sizeof(LineRange),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        chunk_boxes_ = vkt::create_buffer(context.physical, device_, first_chunk * 8ull,
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        object_boxes_ = vkt::create_buffer(
            context.physical, device_, object_count_ * 16ull,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        for (VkDescriptorSet set : sets) {
            const VkBuffer buffers[] = {ranges_.buffer, chunk_boxes_.buffer, object_boxes_.buffer};
            for (uint32_t b = 0; b < 3; ++b)
                vkt::write_buffer_descriptor(device_, set, 7 + b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             buffers[b], 0, VK_WHOLE_SIZE);
        }
        const bool cpu = context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
        const uint32_t constants[] = {cpu ? 64u : 32u, cpu ? 64u : 256u, background};
        tile_ = constants[0];
        const VkSpecializationMapEntry entries[] = {{0, 0, 4}, {1, 4, 4}, {2, 8, 4}};
        const VkSpecializationInfo tile_size{1, entries, 4, constants};
        const VkSpecializationInfo tile_pass{3, entries, sizeof(constants), constants};
        const auto load = [&](const char* name, const VkSpecializationInfo* specialization) {
            vkt::ShaderModule shader = vkt::load_shader(device_, context.chapter, name);
            return vkt::create_compute_pipeline(device_, shader, layout, specialization);
        };
        bounds_ = load("bounds.comp", nullptr);
        bin_ = load("bin.comp", &tile_size);
        tiles_ = load("tiles.comp", &tile_pass);
        resize(context.extent, sets);
    }
    // [/binned-setup]

    // [tile-lists]
    // Per tile, where its list starts and ends; the lists themselves, room
    // for every object in every tile (the most there can be: 250 objects
    // and 60x34 tiles of 32 pixels at 1920x1080 take 2 MiB).
    void resize(VkExtent2D extent, std::span<const VkDescriptorSet> sets) {
        tiles_x_ = uint32_t(vkt::dispatch_count(extent.width, tile_));
        tiles_y_ = uint32_t(vkt::dispatch_count(extent.height, tile_));
        const VkDeviceSize tiles = VkDeviceSize(tiles_x_) * tiles_y_;
        tile_ranges_ = vkt::create_buffer(gpu_.physical, device_, 2 * tiles * 4,
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        tile_lists_ = vkt::create_buffer(gpu_.physical, device_, object_count_ * tiles * 4,
                                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                         VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        for (VkDescriptorSet set : sets) {
            vkt::write_buffer_descriptor(device_, set, 10, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                         tile_ranges_.buffer, 0, VK_WHOLE_SIZE);
            vkt::write_buffer_descriptor(device_, set, 11, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                         tile_lists_.buffer, 0, VK_WHOLE_SIZE);
        }
    }
    // [/tile-lists]

    // [binned-record]
    // The boxes (after zeroing the objects' boxes, which the bounds pass
    // merges into with atomicMax), then the tile lists. The frame's set and
    // push constants are bound already (by the transform pass).
    void bin(VkCommandBuffer cmd) const {
        vkt::buffer_barrier(cmd, object_boxes_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdFillBuffer(cmd, object_boxes_.buffer, 0, VK_WHOLE_SIZE, 0);
        vkt::buffer_barrier(
            cmd, object_boxes_.buffer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        compute_barrier(cmd);  // the transform pass's vertices
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bounds_);
        vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(max_chunks_, group)), object_count_, 1);
        compute_barrier(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, bin_);
        vkCmdDispatch(cmd, 1, 1, 1);
        compute_barrier(cmd);
    }

    // One workgroup per tile, into `pixels` (after the previous frame's copy
    // has read them); every pixel is written, so nothing clears them first.
    void draw(VkCommandBuffer cmd, VkBuffer pixels) const {
        vkt::buffer_barrier(cmd, pixels, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, tiles_);
        vkCmdDispatch(cmd, tiles_x_, tiles_y_, 1);
    }
    // [/binned-record]

    // [verify-raster]
    // --verify raster: the frame drawn by both compute rasterisers, one after
    // the other into the same pixel buffer, each copied out; then every word
    // compared. `transform` records the transform pass (and binds the set).
    void verify(const ComputeRaster& simple, VkExtent2D extent, VkBuffer projected,
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
            draw(cmd, simple.pixels());
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
            throw std::runtime_error(
                "verify: the binned rasteriser's pixel (" + std::to_string(first % extent.width) +
                ", " + std::to_string(first / extent.width) + ") differs from the compute one's");
    }
    // [/verify-raster]

private:
    vkt::Gpu gpu_;
    VkDevice device_;
    uint32_t object_count_ = 0, max_chunks_ = 0;
    uint32_t tile_ = 64, tiles_x_ = 0, tiles_y_ = 0;  // tiles.comp's TILE; tiles across, down
    vkt::Buffer ranges_, chunk_boxes_, object_boxes_, tile_ranges_, tile_lists_;
    vkt::Pipeline bounds_, bin_, tiles_;
};

}  // namespace ch20
