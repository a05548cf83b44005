#pragma once
// Chapter 17's second step, --cull binned: light binning. Instead of every
// tile testing every light, each light works out once which tiles it may
// touch (its rectangle of tiles) and is written into those tiles' bins; the
// tile pass then tests only its bin's candidates. Three compute passes, with
// a barrier after each, run between the G-buffer and the tile pass:
//
//   count  bins.comp, one invocation per light: its view-space sphere and its
//          rectangle, stored; +1 in the bin of every tile of the rectangle
//   scan   bin_scan.comp, one workgroup: each bin's start, the sum of the
//          counts before it (an exclusive prefix sum); the counts back to 0
//   fill   bins.comp again: the light's index into each of its bins
//
// Count, scan and fill make every bin exactly as long as it needs to be, one
// bin after another in one buffer. The buffer itself needs a size before the
// GPU has counted: a budget of candidates, which grows when a frame needed
// more (what the fill could not store is dropped, and reported).

#include "tile_pass.hpp"
#include "vkt/core/barrier.hpp"
#include "vkt/resources/compute.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace ch17 {

constexpr uint32_t bin_group = 256;  // local_size_x of bins.comp

class BinPass {
public:
    // `budget`: room for that many candidates at the start; 0 for the default.
    BinPass(const vkt::Context& context, VkPipelineLayout layout, uint32_t light_count,
            uint32_t budget)
        : gpu_(context.gpu()),
          limits_(context.properties.limits),
          light_count_(light_count),
          budget_(budget) {
        const VkDevice device = gpu_.device;
        // [bin-pipelines]
        vkt::ShaderModule bins = vkt::load_shader(device, context.chapter, "bins.comp");
        for (const VkBool32 fill : {VK_FALSE, VK_TRUE}) {
            const VkSpecializationMapEntry entry{0, 0, sizeof(VkBool32)};
            const VkSpecializationInfo specialization{1, &entry, sizeof fill, &fill};
            (fill ? fill_ : count_) =
                vkt::create_compute_pipeline(device, bins, layout, &specialization);
        }
        scan_ = vkt::create_compute_pipeline(
            device, vkt::load_shader(device, context.chapter, "bin_scan.comp"), layout);
        // [/bin-pipelines]
        // Per light: its sphere (16 bytes) and its rectangle (8 bytes).
        spheres_ = storage(VkDeviceSize{light_count} * 16, "light spheres");
        rects_ = storage(VkDeviceSize{light_count} * 8, "light rectangles");
    }

    // Per tile: its bin's count and start; and the bins' budget, which starts
    // at 4 candidates per light or 64 per tile, whichever is more (at
    // 1920x1080 this scene needs 59 per light at 1,024 lights, at most 35 in
    // a tile; at a million 1.7 per light, about 220 per tile, 1,700 at most).
    void resize(VkExtent2D extent) {
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        counts_ = storage(VkDeviceSize{grid.count()} * 4, "bin counts",
                          VK_BUFFER_USAGE_TRANSFER_DST_BIT);  // cleared every frame
        offsets_ = storage(VkDeviceSize{grid.count()} * 4, "bin offsets");
        const uint64_t budget =
            budget_ ? budget_ : std::max<uint64_t>(4ull * light_count_, 64ull * grid.count());
        if (budget > capacity_) allocate(budget);
    }

    // Bindings 7..11 of set 1 (bins.glsl).
    void write_descriptors(VkDescriptorSet screen_set) const {
        const vkt::Buffer* buffers[] = {&spheres_, &rects_, &counts_, &offsets_, &bins_};
        for (uint32_t i = 0; i < 5; ++i)
            vkt::write_buffer_descriptor(gpu_.device, screen_set, 7 + i,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]->buffer, 0,
                                         VK_WHOLE_SIZE);
    }

    uint32_t capacity() const { return capacity_; }

    // [bin-record]
    // The bins are shared by the frames in flight, like the tiles' lists: the
    // first barrier waits for the last frame's passes to finish with them.
    // Each later barrier makes one pass's writes visible to the next; the last,
    // to the tile pass.
    void record(VkCommandBuffer cmd, const PassSets& sets) const {
        constexpr auto compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        constexpr auto write = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
        constexpr auto read_write = VK_ACCESS_2_SHADER_STORAGE_READ_BIT | write;
        constexpr auto transfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;  // the fill's stage
        vkt::memory_barrier(cmd, compute, write, transfer | compute,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT | read_write);
        vkCmdFillBuffer(cmd, counts_.buffer, 0, VK_WHOLE_SIZE, 0);  // every bin empty
        vkt::memory_barrier(cmd, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, compute, read_write);
        const uint32_t groups = uint32_t(vkt::dispatch_count(light_count_, bin_group));
        const int32_t unused = 0;  // the layout's push constants; these shaders read none
        sets.bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, count_, &unused, sizeof unused);
        vkCmdDispatch(cmd, groups, 1, 1);
        vkt::memory_barrier(cmd, compute, write, compute, read_write);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, scan_);
        vkCmdDispatch(cmd, 1, 1, 1);
        vkt::memory_barrier(cmd, compute, write, compute, read_write);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, fill_);
        vkCmdDispatch(cmd, groups, 1, 1);
        vkt::memory_barrier(cmd, compute, write, compute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    }
    // [/bin-record]

    // After a frame whose bins needed `entries` candidates (TileStats::
    // binned_entries): if that is more than the budget, the fill dropped
    // some; the budget then grows to a quarter more than was needed, once the
    // device is idle, and the caller rewrites the descriptors. True if it grew.
    bool grow(uint32_t entries) {
        if (entries <= capacity_) return false;
        if (entries > limits_.maxStorageBufferRange / 4)
            throw vkt::Error("--cull binned: the bins needed " + std::to_string(entries) +
                             " candidates, more than this device's maxStorageBufferRange (" +
                             std::to_string(limits_.maxStorageBufferRange >> 20) + " MiB) holds");
        VKT_CHECK(vkDeviceWaitIdle(gpu_.device));
        allocate(uint64_t(entries) + entries / 4);
        std::fprintf(stderr, "17_tiled_deferred: the bins needed %u candidates: budget now %u\n",
                     entries, capacity_);
        return true;
    }

private:
    // A device-local storage buffer, refused with its name where one
    // descriptor cannot see it whole.
    vkt::Buffer storage(VkDeviceSize bytes, const char* what, VkBufferUsageFlags more = 0) const {
        if (bytes > limits_.maxStorageBufferRange)
            throw vkt::Error(std::string("--cull binned: the ") + what + " need " +
                             std::to_string(bytes >> 20) + " MiB, more than this device's " +
                             "maxStorageBufferRange (" +
                             std::to_string(limits_.maxStorageBufferRange >> 20) + " MiB)");
        return vkt::create_buffer(gpu_.physical, gpu_.device, bytes,
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | more,
                                  VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    }

    void allocate(uint64_t entries) {
        entries = std::min<uint64_t>(entries, limits_.maxStorageBufferRange / 4);
        bins_ = storage(entries * 4, "bins");
        capacity_ = uint32_t(entries);
    }

    vkt::Gpu gpu_;
    VkPhysicalDeviceLimits limits_;
    uint32_t light_count_, budget_;
    uint32_t capacity_ = 0;  // bin_lights.length()
    vkt::Pipeline count_, scan_, fill_;
    vkt::Buffer spheres_, rects_;          // [light]
    vkt::Buffer counts_, offsets_, bins_;  // [tile], [tile], [capacity_]
};

}  // namespace ch17
