#pragma once
// --verify bins, chapter 17's check of binning: the frame once more, from one
// G-buffer, culled both ways. The tiles' light lists of --cull tiled (every
// tile tests every light) and --cull binned (every tile tests its bin) must
// hold the same lights, tile by tile; and the pictures they light, through
// the fragment pass and the compute pass, must agree.

#include "bin_pass.hpp"
#include "tile_pass.hpp"
#include "vkt/scene/deferred_verify.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace ch17 {

// [verify-bins]
// The tiles' counts and lists, read back after each cull.
struct HostLists {
    vkt::Buffer counts, lists;
};

// Throws vkt::Error when a tile's lists differ, when the pictures differ by
// more than the tolerance, or when the bins dropped candidates.
inline void verify_bins(const vkt::Gpu& gpu, VkExtent2D e, uint32_t light_count,
                        const TilePass& tiles, void* stats,
                        const std::function<void(VkCommandBuffer)>& gbuffer_and_bins,
                        const std::function<void(VkCommandBuffer, VkImageView, bool)>& fragment,
                        const std::function<void(VkCommandBuffer, bool)>& compute) {
    const vkt::TileGrid grid = vkt::tile_grid(e.width, e.height, tile_size);
    const VkDeviceSize count_bytes = VkDeviceSize{grid.count()} * 4;
    const VkDeviceSize list_bytes = count_bytes * max_tile_lights;
    auto host = [&](VkDeviceSize bytes) {
        return vkt::create_buffer(
            gpu.physical, gpu.device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    };
    HostLists lists[2] = {{host(count_bytes), host(list_bytes)},  // [binned]
                          {host(count_bytes), host(list_bytes)}};
    std::vector<vkt::Image> targets;                   // the fragment pass's pictures, [binned]
    std::vector<vkt::deferred::HostCopy> pictures[2];  // [binned]: fragment, then compute
    for (std::vector<vkt::deferred::HostCopy>& copies : pictures) {  // tiled, then binned
        targets.push_back(vkt::create_image_2d(
            gpu.physical, gpu.device, VK_FORMAT_R32G32B32A32_SFLOAT, e,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
            VK_IMAGE_ASPECT_COLOR_BIT));
        copies.push_back(
            vkt::deferred::make_host_copy(gpu.physical, gpu.device, targets.back().image, e, 16));
        copies.push_back(
            vkt::deferred::make_host_copy(gpu.physical, gpu.device, tiles.shaded(), e, 16));
    }
    constexpr auto colour_out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    constexpr auto copy = VK_PIPELINE_STAGE_2_COPY_BIT;
    std::memset(stats, 0, sizeof(TileStats));
    vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        gbuffer_and_bins(cmd);
        for (int binned = 0; binned < 2; ++binned) {
            const VkImage target = targets[binned].image;
            vkt::image_barrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                               VK_ACCESS_2_NONE, colour_out,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
            fragment(cmd, targets[binned].view, binned);  // cull, then light from the lists
            // The lists to the host; the next cull must wait for the copy to read them.
            for (VkBuffer buffer : {tiles.counts(), tiles.lists()})
                vkt::buffer_barrier(cmd, buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, copy,
                                    VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy counts{0, 0, count_bytes}, whole{0, 0, list_bytes};
            vkCmdCopyBuffer(cmd, tiles.counts(), lists[binned].counts.buffer, 1, &counts);
            vkCmdCopyBuffer(cmd, tiles.lists(), lists[binned].lists.buffer, 1, &whole);
            for (VkBuffer buffer : {tiles.counts(), tiles.lists()})
                vkt::buffer_barrier(cmd, buffer, copy, VK_ACCESS_2_NONE,
                                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            vkt::image_barrier(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colour_out,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, copy,
                               VK_ACCESS_2_TRANSFER_READ_BIT);
            compute(cmd, binned);  // cull and shade; leaves the image in TRANSFER_SRC_OPTIMAL
            vkt::deferred::record_host_copies(cmd, e, pictures[binned]);
            vkt::image_barrier(cmd, tiles.shaded(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               VK_IMAGE_LAYOUT_GENERAL, copy, VK_ACCESS_2_NONE,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
    });
    TileStats counted{};
    std::memcpy(&counted, stats, sizeof counted);
    std::memset(stats, 0, sizeof counted);

    // Tile by tile: the same count, and the same lights in any order (each
    // list is in the order its tile's atomics ran). A list that overflowed
    // keeps whichever 2,048 (max_tile_lights) came first, so there only the
    // counts must agree.
    const auto* counts = static_cast<const uint32_t*>(lists[0].counts.mapped);
    const auto* binned_counts = static_cast<const uint32_t*>(lists[1].counts.mapped);
    uint32_t differ = 0, overflowed = 0, first_differ = 0;
    uint64_t kept = 0;
    for (uint32_t tile = 0; tile < grid.count(); ++tile) {
        const uint32_t n = std::min(counts[tile], max_tile_lights);
        std::vector<uint32_t> list[2];
        for (int binned = 0; binned < 2; ++binned) {
            const auto* all = static_cast<const uint32_t*>(lists[binned].lists.mapped);
            list[binned].assign(all + size_t{tile} * max_tile_lights,
                                all + size_t{tile} * max_tile_lights + n);
            std::sort(list[binned].begin(), list[binned].end());
        }
        kept += counts[tile];
        overflowed += counts[tile] > max_tile_lights;
        const bool same = counts[tile] == binned_counts[tile] &&
                          (counts[tile] > max_tile_lights || list[0] == list[1]);
        if (!same && differ++ == 0) first_differ = tile;
    }
    std::fprintf(stderr,
                 "17_tiled_deferred: verify bins: %u tiles, %llu lights kept in all (%u lights, "
                 "%ux%u pixels); lists that differ: %u; overflowed (counts compared): %u\n",
                 grid.count(), (unsigned long long)kept, light_count, e.width, e.height, differ,
                 overflowed);
    // The pictures, but for the tiles that overflowed: each list kept a
    // different 2,048, so their pixels may differ.
    float difference[2] = {};
    for (int shade = 0; shade < 2; ++shade) {
        std::vector<glm::vec3> picture[2];
        for (int binned = 0; binned < 2; ++binned) {
            picture[binned] = vkt::deferred::host_colours(pictures[binned][shade]);
            for (uint32_t y = 0; y < e.height; ++y)
                for (uint32_t x = 0; x < e.width; ++x)
                    if (counts[(y / tile_size) * grid.x + x / tile_size] > max_tile_lights)
                        picture[binned][size_t{y} * e.width + x] = glm::vec3(0.0f);
        }
        difference[shade] = vkt::deferred::max_linear_difference(picture[0], picture[1]);
    }
    constexpr float tolerance = 1e-4f;  // the same sums, in another order
    for (int shade = 0; shade < 2; ++shade)
        std::fprintf(stderr,
                     "17_tiled_deferred: verify bins: binned vs tiled, shade %s, largest "
                     "difference %g (tolerance %g)%s\n",
                     shade ? "compute" : "fragment", difference[shade], tolerance,
                     overflowed ? ", overflowed tiles left out" : "");
    if (counted.binned_entries > counted.binned_budget)
        throw vkt::Error("--verify bins: the bins needed " +
                         std::to_string(counted.binned_entries) + " candidates, above their " +
                         "budget of " + std::to_string(counted.binned_budget) +
                         ": some were dropped");
    if (differ != 0)
        throw vkt::Error("--verify bins: " + std::to_string(differ) +
                         " tiles' lists differ, the first tile " + std::to_string(first_differ) +
                         ": tiled kept " + std::to_string(counts[first_differ]) +
                         " lights, binned " + std::to_string(binned_counts[first_differ]));
    for (float d : difference)
        if (!(d <= tolerance))
            throw vkt::Error("--verify bins: the pictures differ by " + std::to_string(d) +
                             ", above " + std::to_string(tolerance));
}
// [/verify-bins]

}  // namespace ch17
