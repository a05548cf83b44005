#pragma once
// --verify brute, chapter 17's check: the frame once more, into float images,
// through chapter 16's brute-force lighting pass, the tiled fragment pass and
// the tiled compute pass; the three are read back (with chapter 16's helpers,
// vkt/scene/deferred_verify.hpp) and compared pairwise.

#include "tile_pass.hpp"
#include "vkt/scene/deferred_verify.hpp"

#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace ch17 {

// The passes, recorded into any command buffer; each lights from the same
// G-buffer.
struct BrutePasses {
    std::function<void(VkCommandBuffer)> gbuffer;                      // both barriers and pass 1
    std::function<void(VkCommandBuffer, VkImageView)> brute;           // every light, every pixel
    std::function<void(VkCommandBuffer, VkImageView)> tiled_fragment;  // cull, then lighting
    std::function<void(VkCommandBuffer)> tiled_compute;  // cull and shade into `shaded`
};

// [verify]
// Throws vkt::Error when the pictures differ by more than the tolerance, or
// when a tile's list overflowed (its pixels then miss lights). `stats` is the
// TileStats buffer the passes count into.
inline void verify_brute(const vkt::Gpu& gpu, VkExtent2D e, uint32_t light_count, VkImage shaded,
                         void* stats, const BrutePasses& passes) {
    const VkPhysicalDevice physical = gpu.physical;
    std::vector<vkt::Image> targets;  // brute force, tiled fragment
    std::vector<vkt::deferred::HostCopy> copies;
    for (int i = 0; i < 2; ++i) {
        targets.push_back(vkt::create_image_2d(
            physical, gpu.device, VK_FORMAT_R32G32B32A32_SFLOAT, e,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
            VK_IMAGE_ASPECT_COLOR_BIT));
        copies.push_back(
            vkt::deferred::make_host_copy(physical, gpu.device, targets[i].image, e, 16));
    }
    copies.push_back(vkt::deferred::make_host_copy(physical, gpu.device, shaded, e, 16));
    constexpr auto colour_out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    std::memset(stats, 0, sizeof(TileStats));
    vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        for (const vkt::Image& target : targets)
            vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                               VK_ACCESS_2_NONE, colour_out,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        passes.gbuffer(cmd);
        passes.brute(cmd, targets[0].view);
        passes.tiled_fragment(cmd, targets[1].view);
        passes.tiled_compute(cmd);
        for (const vkt::Image& target : targets)
            vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colour_out,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                               VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::deferred::record_host_copies(cmd, e, copies);
        vkt::image_barrier(cmd, shaded, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE);
    });
    TileStats counted{};
    std::memcpy(&counted, stats, sizeof counted);
    std::memset(stats, 0, sizeof counted);
    const auto brute = vkt::deferred::host_colours(copies[0]),
               fragment = vkt::deferred::host_colours(copies[1]),
               compute = vkt::deferred::host_colours(copies[2]);
    // [compare]
    const struct {
        const char* what;
        float difference;
    } results[] = {
        {"tiled fragment vs brute force", vkt::deferred::max_linear_difference(fragment, brute)},
        {"tiled compute vs brute force", vkt::deferred::max_linear_difference(compute, brute)},
        {"tiled fragment vs tiled compute",
         vkt::deferred::max_linear_difference(fragment, compute)},
    };
    constexpr float tolerance = 1e-4f;
    for (const auto& r : results)
        std::fprintf(stderr,
                     "17_tiled_deferred: verify brute: %s, largest difference %g "
                     "(tolerance %g), %ux%u pixels, %u lights\n",
                     r.what, r.difference, tolerance, e.width, e.height, light_count);
    std::fprintf(stderr,
                 "17_tiled_deferred: verify brute: the most lights in a tile %u, "
                 "tiles overflowed %u\n",
                 counted.most_lights, counted.overflowed_tiles);
    if (counted.overflowed_tiles != 0)
        throw vkt::Error("--verify brute: " + std::to_string(counted.overflowed_tiles) +
                         " tiles had more than " + std::to_string(max_tile_lights) +
                         " lights; their lists dropped lights");
    for (const auto& r : results)
        if (!(r.difference <= tolerance))
            throw vkt::Error(std::string("--verify brute: ") + r.what + " differ by " +
                             std::to_string(r.difference) + ", above " + std::to_string(tolerance));
    // [/compare]
}
// [/verify]

}  // namespace ch17
