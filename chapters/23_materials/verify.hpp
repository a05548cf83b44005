#pragma once
// Chapter 23's --verify: the last frame's HDR target read back (chapter 16's
// host copies) and compared with the CPU reference, vkt/scene/pbr.hpp.
//
//   cpu      at three points of each sphere (its centre, and its centre moved
//            by (-0.5, 0.5) and (0.5, 0) radii in world x and y: 0.71 and
//            0.5 radii off it), the radiance the GPU wrote against
//            vkt::pbr::shade for the point the pixel's centre sees on the
//            exact sphere: within 2% + 0.005 in every channel
//   furnace  every pixel of the white sphere under the white sky, where it
//            faces the eye at n.v >= 0.3: within 3% of 1 (the sky's radiance)
//   lut      the image-based light's BRDF table against the CPU's integration

#include "environment.hpp"
#include "grid.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/scene/deferred_verify.hpp"
#include "vkt/scene/pbr.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace verify {

// The HDR target (R16G16B16A16_SFLOAT, left SHADER_READ_ONLY_OPTIMAL by the
// tone-mapping pass) as linear RGB, row by row.
inline std::vector<glm::vec3> read_hdr(const vkt::Gpu& gpu, VkImage image, VkExtent2D extent) {
    std::vector<vkt::deferred::HostCopy> copies;
    copies.push_back(vkt::deferred::make_host_copy(gpu.physical, gpu.device, image, extent, 8));
    vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        vkt::image_barrier(cmd, image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::deferred::record_host_copies(cmd, extent, copies);
    });
    const std::vector<uint16_t> halves = vkt::deferred::host_values<uint16_t>(copies[0]);
    std::vector<glm::vec3> out(size_t(extent.width) * extent.height);
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = {glm::unpackHalf1x16(halves[4 * i]), glm::unpackHalf1x16(halves[4 * i + 1]),
                  glm::unpackHalf1x16(halves[4 * i + 2])};
    return out;
}

// Where the ray through pixel (x, y)'s centre first meets `sphere`, if it does.
inline std::optional<glm::vec3> hit(const glm::mat4& world_from_clip, VkExtent2D extent, int x,
                                    int y, const grid::Sphere& sphere) {
    const glm::vec2 ndc{(float(x) + 0.5f) / float(extent.width) * 2.0f - 1.0f,
                        (float(y) + 0.5f) / float(extent.height) * 2.0f - 1.0f};
    const glm::vec4 far = world_from_clip * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 d = glm::normalize(glm::vec3(far) / far.w - grid::eye);
    const glm::vec3 o = grid::eye - sphere.centre;
    const float b = glm::dot(o, d), c = glm::dot(o, o) - sphere.radius * sphere.radius;
    if (b * b - c < 0.0f) return std::nullopt;
    return grid::eye + d * (-b - std::sqrt(b * b - c));
}

inline void check(const std::string& which, const std::vector<glm::vec3>& hdr, VkExtent2D extent,
                  bool furnace) {
    const glm::mat4 clip = grid::clip_from_world(float(extent.width) / float(extent.height));
    const glm::mat4 world_from_clip = glm::inverse(clip);
    const auto lights = grid::lights(furnace);
    int points = 0;
    float worst = 0.0f, low = 1e9f, high = -1e9f;
    for (const grid::Sphere& s : grid::spheres(furnace)) {
        std::vector<glm::ivec2> pixels;
        if (which == "cpu") {
            for (glm::vec2 offset : {glm::vec2(0.0f), glm::vec2(-0.5f, 0.5f), glm::vec2(0.5f, 0)}) {
                const glm::vec4 p = clip * glm::vec4(s.centre + s.radius * glm::vec3(offset, 0), 1);
                pixels.emplace_back((glm::vec2(p) / p.w * 0.5f + 0.5f) *
                                    glm::vec2(float(extent.width), float(extent.height)));
            }
        } else {  // furnace: every pixel
            for (int y = 0; y < int(extent.height); ++y)
                for (int x = 0; x < int(extent.width); ++x) pixels.emplace_back(x, y);
        }
        for (glm::ivec2 pixel : pixels) {
            const std::optional<glm::vec3> p = hit(world_from_clip, extent, pixel.x, pixel.y, s);
            if (!p) continue;
            // Near the silhouette (n.v < 0.3) single scattering loses more: the page.
            const glm::vec3 n = glm::normalize(*p - s.centre), v = glm::normalize(grid::eye - *p);
            if (which == "furnace" && glm::dot(n, v) < 0.3f) continue;
            const glm::vec3 gpu = hdr[size_t(pixel.y) * extent.width + size_t(pixel.x)];
            ++points;
            if (which == "furnace") {
                low = std::min({low, gpu.r, gpu.g, gpu.b});
                high = std::max({high, gpu.r, gpu.g, gpu.b});
                continue;
            }
            const glm::vec3 cpu =
                vkt::pbr::shade(n, v, s.material, lights, grid::sky(furnace), grid::sky_samples);
            const glm::vec3 off = glm::abs(gpu - cpu) / (0.005f + 0.02f * cpu);
            worst = std::max({worst, off.r, off.g, off.b});
            if (std::max({off.r, off.g, off.b}) > 1.0f)
                throw vkt::Error("--verify cpu: pixel (" + std::to_string(pixel.x) + ", " +
                                 std::to_string(pixel.y) + ") is (" + std::to_string(gpu.r) + ", " +
                                 std::to_string(gpu.g) + ", " + std::to_string(gpu.b) +
                                 "); the CPU reference says (" + std::to_string(cpu.r) + ", " +
                                 std::to_string(cpu.g) + ", " + std::to_string(cpu.b) + ")");
        }
    }
    if (points == 0) throw vkt::Error("--verify " + which + ": no pixel shows a sphere");
    if (which == "furnace") {
        std::fprintf(stderr, "23_materials: verify furnace: %d pixels from %.4f to %.4f\n", points,
                     double(low), double(high));
        if (low < 0.97f || high > 1.03f)
            throw vkt::Error("--verify furnace: the white sphere ranges from " +
                             std::to_string(low) + " to " + std::to_string(high) +
                             " under a sky of 1, more than 3% off");
        return;
    }
    std::fprintf(stderr,
                 "23_materials: verify cpu: %d points match the CPU reference, the largest "
                 "difference %.0f%% of the tolerance\n",
                 points, double(100.0f * worst));
}

// [verify-lut]
// --verify lut: the GPU's BRDF table (size x size texels, `samples` per
// texel) against split_sum_lut on the CPU at nine texels, n.v and roughness
// each near 0.1, 0.5 and 0.95: with the same samples within 0.002 (the GPU
// computes the formula: half floats round by up to 0.0005), and with 16
// times as many within 0.02 (the table's samples are enough: a grazing view
// converges slowest, lavapipe's table 0.0102 off at n.v 0.11, roughness 0.52).
inline void check_lut(const std::vector<glm::vec3>& table, uint32_t size, uint32_t samples) {
    float worst[2] = {0.0f, 0.0f};
    for (uint32_t y : {size / 10, size / 2, size - 2})
        for (uint32_t x : {size / 10, size / 2, size - 2}) {
            const float n_dot_v = (float(x) + 0.5f) / float(size);
            const float roughness = (float(y) + 0.5f) / float(size);
            const glm::vec3 gpu = table[size_t(y) * size + x];
            for (int check = 0; check < 2; ++check) {
                const float tolerance = check == 0 ? 0.002f : 0.02f;
                const uint32_t count = check == 0 ? samples : 16 * samples;
                const glm::vec2 cpu = vkt::pbr::split_sum_lut(n_dot_v, roughness, count);
                const float off = std::max(std::abs(gpu.x - cpu.x), std::abs(gpu.y - cpu.y));
                worst[check] = std::max(worst[check], off);
                if (off > tolerance)
                    throw vkt::Error("--verify lut: at n.v " + std::to_string(n_dot_v) +
                                     ", roughness " + std::to_string(roughness) +
                                     " the table holds (" + std::to_string(gpu.x) + ", " +
                                     std::to_string(gpu.y) + "); " + std::to_string(count) +
                                     " samples on the CPU give (" + std::to_string(cpu.x) + ", " +
                                     std::to_string(cpu.y) + ")");
            }
        }
    std::fprintf(stderr,
                 "23_materials: verify lut: 9 points match the CPU integration, with the same "
                 "samples within 0.002 (at most %.4f off), with 16 times as many within 0.02 (at "
                 "most %.4f off)\n",
                 double(worst[0]), double(worst[1]));
}
// [/verify-lut]

// The table environment.hpp made at start-up, read back and checked.
inline void check_lut(const vkt::Gpu& gpu, const Environment& environment) {
    check_lut(read_hdr(gpu, environment.lut(), {Environment::lut_size, Environment::lut_size}),
              Environment::lut_size, Environment::lut_samples);
}

}  // namespace verify
