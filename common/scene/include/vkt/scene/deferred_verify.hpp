#pragma once
// Chapter 16's checks (--verify), kept out of main.cpp: copying images to
// host-visible buffers, and the three comparisons the tests run.
//
//   cpu:        the lit image against vkt::shade_gbuffer on the read-back G-buffer
//   additivity: lights A, then lights B, summed, against A and B in one pass;
//               and lights moved out of reach add exactly nothing
//   forward:    the forward path's picture against the deferred one

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/resources/srgb.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/deferred_blocks.hpp"
#include "vkt/scene/gbuffer.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace vkt::deferred {

// A host-visible buffer that an image of `bytes_per_texel` is copied into.
struct HostCopy {
    vkt::Buffer buffer;
    VkImage image = VK_NULL_HANDLE;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

inline HostCopy make_host_copy(VkPhysicalDevice physical, VkDevice device, VkImage image,
                               VkExtent2D extent, uint32_t bytes_per_texel,
                               VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT) {
    return {vkt::create_buffer(
                physical, device, VkDeviceSize{extent.width} * extent.height * bytes_per_texel,
                VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT),
            image, aspect};
}

// Records the copy of each image (in TRANSFER_SRC_OPTIMAL) into its buffer,
// and the barrier that makes the copies visible to the host.
inline void record_host_copies(VkCommandBuffer cmd, VkExtent2D extent,
                               const std::vector<HostCopy>& copies) {
    for (const HostCopy& copy : copies) {
        const VkBufferImageCopy region{
            .imageSubresource = {copy.aspect, 0, 0, 1},
            .imageExtent = {extent.width, extent.height, 1},
        };
        vkCmdCopyImageToBuffer(cmd, copy.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               copy.buffer.buffer, 1, &region);
    }
    vkt::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

template <typename T>
std::vector<T> host_values(const HostCopy& copy) {
    std::vector<T> out(copy.buffer.size / sizeof(T));
    std::memcpy(out.data(), copy.buffer.mapped, out.size() * sizeof(T));
    return out;
}

// An R32G32B32A32_SFLOAT image as RGB colours.
inline std::vector<glm::vec3> host_colours(const HostCopy& copy) {
    const std::vector<glm::vec4> texels = host_values<glm::vec4>(copy);
    return {texels.begin(), texels.end()};
}

// What the screen would show: linear -> sRGB, clamped, in 0..255 (unrounded).
inline float srgb_255(float linear) {
    return 255.0f * linear_to_srgb(std::clamp(linear, 0.0f, 1.0f));
}

// The largest difference of any channel of any pixel, in linear units, and
// relative to the value where that is above 1 (lit colours may exceed 1).
inline float max_linear_difference(const std::vector<glm::vec3>& a,
                                   const std::vector<glm::vec3>& b) {
    float worst = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst =
                std::max(worst, std::abs(a[i][c] - b[i][c]) /
                                    std::max(1.0f, std::max(std::abs(a[i][c]), std::abs(b[i][c]))));
    return worst;
}

// The same, after sRGB encoding, in levels of 255 (what a screenshot stores).
inline float max_screen_difference(const std::vector<glm::vec3>& a,
                                   const std::vector<glm::vec3>& b) {
    float worst = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(srgb_255(a[i][c]) - srgb_255(b[i][c])));
    return worst;
}

// What verify needs from the renderer: the frame's inputs, and its passes,
// recorded into any command buffer.
struct VerifyInputs {
    vkt::Gpu gpu;
    VkExtent2D extent;
    VkImage gbuffer[4];  // base colour, normal, material, depth
    glm::mat4 inverse_view_proj;
    glm::vec3 eye, ambient;
    std::span<const vkt::PointLight> lights;
};
struct VerifyPasses {
    std::function<void(VkCommandBuffer)> gbuffer;  // both barriers and pass 1
    std::function<void(VkCommandBuffer, VkImageView, const LightingPush&)> lighting;
    std::function<void(VkCommandBuffer, VkImageView)> forward;  // depth barrier and pass
};

// --verify cpu lights every drawn texel with every light on one CPU core,
// twice: at 65,536 lights and 800x600 that is some 40 minutes on lavapipe's
// machine. Where the work is large (from 2.5e8 light evaluations, some
// seconds), say so before it starts, estimate the whole once 2% is done,
// then a line every 10% with the time left at the rate so far. Progress
// counts drawn texels (the background costs nothing). Output only: nothing
// is decided by the clock.
class CpuProgress {
public:
    CpuProgress(VkExtent2D extent, std::span<const float> depth, size_t lights, int passes)
        : passes_(passes) {
        drawn_.assign(extent.height + 1, 0);
        for (uint32_t y = 0; y < extent.height; ++y) {
            drawn_[y + 1] = drawn_[y];
            for (uint32_t x = 0; x < extent.width; ++x)
                drawn_[y + 1] += depth[size_t{y} * extent.width + x] != 1.0f ? 1 : 0;
        }
        const double work = double(drawn_.back()) * double(lights) * passes;
        shown_ = work >= 2.5e8;
        if (shown_)
            std::fprintf(stderr,
                         "16_deferred: verify cpu: lighting %zu drawn texels with %zu lights on "
                         "the CPU, %d passes (%.3g light evaluations): progress every 10%%\n",
                         drawn_.back(), lights, passes, work);
    }
    // What shade_gbuffer calls after each row of pass `pass` (from 0); none
    // where the work is small.
    std::function<void(uint32_t)> pass(int pass) {
        if (!shown_) return {};
        return [this, pass](uint32_t rows) {
            const double done = (pass + double(drawn_[rows]) / double(drawn_.back())) / passes_;
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
            if (!estimated_ && done >= 0.02) {
                estimated_ = true;
                std::fprintf(stderr, "16_deferred: verify cpu: about %.0f s in all\n",
                             elapsed / done);
            }
            if (done * 10 < next_tenth_) return;
            next_tenth_ = int(done * 10) + 1;
            std::fprintf(stderr, "16_deferred: verify cpu: %.0f%% done, about %.0f s left\n",
                         done * 100, elapsed / done - elapsed);
        };
    }

private:
    std::vector<size_t> drawn_;  // drawn texels in the rows above each row
    int passes_;
    bool shown_ = false, estimated_ = false;
    int next_tenth_ = 1;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Renders the frame once more into float targets (the lighting pass with
// several light ranges, its albedo view, and the forward path), reads them and
// the G-buffer back, and runs `check`. Throws vkt::Error when it fails. The
// passes' lights n .. 2n - 1 must be copies of the n lights lifted 1000 units
// up, out of everything's reach.
inline void verify(const std::string& check, const VerifyInputs& in, const VerifyPasses& passes) {
    const VkPhysicalDevice physical = in.gpu.physical;
    const VkDevice device = in.gpu.device;
    const VkExtent2D e = in.extent;
    const uint32_t n = uint32_t(in.lights.size()), half = n / 2;

    enum { lit, only_a, only_b, a_and_b, out_of_reach, albedo, forward, target_count };
    const LightingPush pushes[] = {{view_lit, 0, n, 1.0f},           {view_lit, 0, half, 0.0f},
                                   {view_lit, half, n - half, 0.0f}, {view_lit, 0, n, 0.0f},
                                   {view_lit, n, n, 0.0f},           {view_albedo, 0, 0, 0.0f}};
    std::vector<vkt::Image> targets;
    std::vector<HostCopy> copies;
    for (int i = 0; i < target_count; ++i) {
        targets.push_back(vkt::create_image_2d(
            physical, device, VK_FORMAT_R32G32B32A32_SFLOAT, e,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
            VK_IMAGE_ASPECT_COLOR_BIT));
        copies.push_back(make_host_copy(physical, device, targets[i].image, e, 16));
    }
    for (int i = 0; i < 4; ++i)
        copies.push_back(
            make_host_copy(physical, device, in.gbuffer[i], e, 4,
                           i == 3 ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT));

    constexpr auto colour_out = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    constexpr auto fragment = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    constexpr auto copy = VK_PIPELINE_STAGE_2_COPY_BIT;
    vkt::one_time_submit(in.gpu, [&](VkCommandBuffer cmd) {
        for (const vkt::Image& target : targets)
            vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                               VK_ACCESS_2_NONE, colour_out,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        passes.gbuffer(cmd);
        for (int i = lit; i <= albedo; ++i) passes.lighting(cmd, targets[i].view, pushes[i]);
        passes.forward(cmd, targets[forward].view);
        for (const vkt::Image& target : targets)
            vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colour_out,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, copy,
                               VK_ACCESS_2_TRANSFER_READ_BIT);
        for (int i = 0; i < 4; ++i)  // from the lighting pass's reads to the copy, and back
            vkt::image_barrier(cmd, in.gbuffer[i],
                               i == 3 ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                                      : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, fragment, VK_ACCESS_2_NONE,
                               copy, VK_ACCESS_2_TRANSFER_READ_BIT,
                               copies[target_count + i].aspect);
        record_host_copies(cmd, e, copies);
        for (int i = 0; i < 4; ++i)
            vkt::image_barrier(cmd, in.gbuffer[i], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               VK_IMAGE_LAYOUT_GENERAL, copy, VK_ACCESS_2_NONE, fragment,
                               VK_ACCESS_2_NONE, copies[target_count + i].aspect);
    });

    std::vector<std::vector<glm::vec3>> pictures;
    pictures.reserve(target_count);
    for (int i = 0; i < target_count; ++i) pictures.push_back(host_colours(copies[i]));
    vkt::GBufferTexels texels{e.width,
                              e.height,
                              host_values<uint8_t>(copies[target_count]),
                              host_values<int16_t>(copies[target_count + 1]),
                              host_values<uint8_t>(copies[target_count + 2]),
                              host_values<float>(copies[target_count + 3])};
    // Only pixels where something was drawn are lit; the rest show the background.
    auto drawn_only = [&](std::vector<glm::vec3> picture) {
        for (size_t i = 0; i < picture.size(); ++i)
            if (texels.depth[i] == 1.0f) picture[i] = glm::vec3(0.0f);
        return picture;
    };
    float difference = 0, tolerance = 0;
    const char* what = "";
    if (check == "cpu") {
        // The CPU lights the read-back G-buffer: the same numbers the GPU read.
        // First with its own (exact) sRGB decoding of the base colour, then
        // with the base colour as the GPU decoded it: the lighting alone.
        const glm::vec3 background(0.02f, 0.02f, 0.04f);
        CpuProgress progress(e, texels.depth, in.lights.size(), 2);
        const float whole = max_linear_difference(
            pictures[lit], vkt::shade_gbuffer(texels, in.inverse_view_proj, in.eye, in.ambient,
                                              in.lights, background, progress.pass(0)));
        std::fprintf(stderr,
                     "16_deferred: verify cpu: with the CPU's own sRGB decoding, largest "
                     "difference %g (tolerance 0.005)\n",
                     whole);
        if (!(whole <= 0.005f)) throw vkt::Error("--verify cpu: the G-buffer decodes wrongly");
        texels.albedo_as_read = pictures[albedo];
        difference = max_linear_difference(
            pictures[lit], vkt::shade_gbuffer(texels, in.inverse_view_proj, in.eye, in.ambient,
                                              in.lights, background, progress.pass(1)));
        // GPUs may evaluate pow, exp2, log2 and inversesqrt approximately (the
        // precision rules of the Vulkan environment for SPIR-V), and pow's
        // error grows with the shininess exponent: lavapipe comes within 6e-6,
        // an NVIDIA H100 within 9e-4. 2e-3 is half a step of an 8-bit value,
        // too small to show in a screenshot; a wrong term costs 1e-2 or more.
        tolerance = 2e-3f;
        what = "GPU lighting pass vs CPU reference (vkt::shade_gbuffer), largest difference";
    } else if (check == "additivity") {
        std::vector<glm::vec3> sum(pictures[lit].size());
        for (size_t i = 0; i < sum.size(); ++i) sum[i] = pictures[only_a][i] + pictures[only_b][i];
        difference = max_linear_difference(drawn_only(sum), drawn_only(pictures[a_and_b]));
        tolerance = 1e-5f;
        const float stray = max_linear_difference(drawn_only(pictures[out_of_reach]),
                                                  std::vector<glm::vec3>(sum.size()));
        std::fprintf(
            stderr, "16_deferred: verify: lights out of reach add at most %g (must be 0)\n", stray);
        if (stray != 0.0f) throw vkt::Error("--verify additivity: a light beyond its radius shone");
        what = "lights A + lights B vs A and B together, largest difference";
    } else {
        difference = max_screen_difference(pictures[forward], pictures[lit]);
        tolerance = 1.5f;
        what = "forward vs deferred, largest difference in sRGB levels of 255";
    }
    std::fprintf(stderr, "16_deferred: verify %s: %s %g (tolerance %g), %ux%u pixels, %u lights\n",
                 check.c_str(), what, difference, tolerance, e.width, e.height, n);
    if (!(difference <= tolerance))
        throw vkt::Error("--verify " + check + ": the difference " + std::to_string(difference) +
                         " is above the tolerance " + std::to_string(tolerance));
}

}  // namespace vkt::deferred
