#pragma once
// Chapter 23's image-based light (--sky environment). An HDR sky is made at
// start-up into a cube map, and from it, by compute dispatches in one command
// buffer before the first frame, the three images the split-sum
// approximation reads: the diffuse irradiance cube, the prefiltered specular
// cube (one mip level per roughness step) and the BRDF lookup table. The
// scene pass reads them (set 2), and draws the sky behind the spheres.

#include "blocks.hpp"
#include "cube_map.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/frame/gpu_timer.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"
#include "vkt/resources/upload.hpp"

#include <glm/glm.hpp>

#include <cstdio>
#include <string>
#include <vector>

class Environment {
public:
    // [ibl-sizes]
    // Texels along a face's side (a cube has six faces), and samples per texel.
    static constexpr uint32_t sky_size = 128, sky_levels = 8;  // 128, 64, .. 1
    static constexpr uint32_t irradiance_size = 32, irradiance_samples = 128;
    static constexpr uint32_t specular_size = 64, specular_levels = 6;  // roughness 0, 0.2, .. 1
    static constexpr uint32_t specular_samples = 128;
    static constexpr uint32_t lut_size = 32, lut_samples = 1024;
    static constexpr VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
    // [/ibl-sizes]

    Environment(const vkt::Gpu& gpu, const std::string& chapter, glm::vec3 sun, bool furnace)
        : gpu_(gpu) {
        const VkDevice device = gpu.device;
        sky_ = make_cube(gpu, sky_size, sky_levels, format);
        irradiance_ = make_cube(gpu, irradiance_size, 1, format);
        specular_ = make_cube(gpu, specular_size, specular_levels, format);
        // The table is a plain 2D image; --verify lut copies it out.
        lut_ = vkt::create_image_2d(gpu.physical, device, format, {lut_size, lut_size},
                                    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                        VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    VK_IMAGE_ASPECT_COLOR_BIT);
        sampler_ = clamped_sampler(device);

        // Each step reads one image (binding 0) and writes another (binding 1).
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
        step_layout_ = vkt::create_descriptor_set_layout(device, bindings);
        // The scene's set 2: the sky, irradiance, specular and the table.
        VkDescriptorSetLayoutBinding scene[4];
        for (uint32_t b = 0; b < 4; ++b)
            scene[b] = {b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
        scene_layout_ = vkt::create_descriptor_set_layout(device, scene);
        const uint32_t steps = sky_levels + 1 + specular_levels + 1;
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, steps + 4},
            {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, steps}};
        pool_ = vkt::create_descriptor_pool(device, steps + 1, sizes);
        scene_set_ = vkt::allocate_descriptor_set(device, pool_, scene_layout_);
        const VkImageView scene_views[] = {sky_.image.view, irradiance_.image.view,
                                           specular_.image.view, lut_.view};
        for (uint32_t b = 0; b < 4; ++b)
            vkt::write_image_descriptor(device, scene_set_, b, scene_views[b], sampler_,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);

        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(EnvironmentPush)};
        const VkDescriptorSetLayout layouts[] = {step_layout_};
        pipeline_layout_ = vkt::create_pipeline_layout(device, layouts, {&push, 1});
        for (const char* name :
             {"sky.comp", "downsample.comp", "irradiance.comp", "prefilter.comp", "brdf_lut.comp"})
            pipelines_.push_back(vkt::create_compute_pipeline(
                device, vkt::load_shader(device, chapter, name), pipeline_layout_));
        precompute(sun, furnace);
    }

    VkDescriptorSetLayout layout() const { return scene_layout_; }
    VkDescriptorSet set() const { return scene_set_; }
    VkImage lut() const { return lut_.image; }

    // [background]
    // The sky behind everything, drawn first in the scene pass with the
    // scene's pipeline layout (set 0: the frame's block; set 2: these
    // images, which stay bound for the spheres), the full-screen triangle of
    // chapter 16, neither testing nor writing depth.
    void make_background(VkPipelineLayout layout, VkShaderModule vertex, VkShaderModule fragment,
                         VkFormat colour, VkFormat depth) {
        background_ =
            vkt::create_graphics_pipeline(gpu_.device, {.vertex = vertex,
                                                        .fragment = fragment,
                                                        .layout = layout,
                                                        .color_formats = {colour},
                                                        .depth_format = depth,
                                                        .depth_write = false,
                                                        .depth_compare = VK_COMPARE_OP_ALWAYS});
    }
    void draw_background(VkCommandBuffer cmd, VkPipelineLayout layout) const {
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &scene_set_, 0,
                                nullptr);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, background_);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    // [/background]

private:
    // One step: `pipeline` reads `source` (none for the sky and the table)
    // and writes `target`, one invocation per texel of a size x size face,
    // `faces` faces.
    void dispatch(VkCommandBuffer cmd, uint32_t pipeline, VkImageView source, VkImageView target,
                  const EnvironmentPush& push, uint32_t size, uint32_t faces) {
        const VkDescriptorSet set = vkt::allocate_descriptor_set(gpu_.device, pool_, step_layout_);
        if (source != VK_NULL_HANDLE)
            vkt::write_image_descriptor(gpu_.device, set, 0, source, sampler_,
                                        VK_IMAGE_LAYOUT_GENERAL);
        vkt::write_storage_image_descriptor(gpu_.device, set, 1, target);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[pipeline]);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set,
                                0, nullptr);
        vkCmdPushConstants(cmd, pipeline_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push,
                           &push);
        const auto groups = uint32_t(vkt::dispatch_count(size, 8));
        vkCmdDispatch(cmd, groups, groups, faces);
    }

    void precompute(glm::vec3 sun, bool furnace) {
        vkt::GpuTimer timer(gpu_.physical, gpu_.device, gpu_.queue_family, 1);
        const VkImage images[] = {sky_.image.image, irradiance_.image.image, specular_.image.image,
                                  lut_.image};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                          VK_REMAINING_ARRAY_LAYERS};
        EnvironmentPush push{glm::vec4(sun, furnace ? 1.0f : 0.0f), 0.0f, 0, float(sky_size)};
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            timer.begin(cmd, 0);
            // Every image from nothing to GENERAL, where compute shaders
            // write them (and the sky's levels are read as they are made).
            for (VkImage image : images)
                vkt::image_barrier(cmd, image, all, VK_IMAGE_LAYOUT_UNDEFINED,
                                   VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, 0,
                                   VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                   VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            // [precompute]
            // Storage writes, then the next dispatch's sampled reads.
            const auto written = [&] {
                vkt::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
            };
            {
                // The sky's level 0 from its formula, then each level from the one above.
                auto scope = vkt::GpuScope(&timer, cmd, 0, "sky");
                dispatch(cmd, 0, VK_NULL_HANDLE, sky_.level[0], push, sky_size, 6);
                for (uint32_t level = 1; level < sky_levels; ++level) {
                    written();
                    dispatch(cmd, 1, sky_.level[level - 1], sky_.level[level], push,
                             sky_size >> level, 6);
                }
                written();
            }
            // [/precompute]
            // The three images read the whole sky and not each other: no
            // barrier between them.
            {
                auto scope = vkt::GpuScope(&timer, cmd, 0, "irradiance");
                push.samples = irradiance_samples;
                dispatch(cmd, 2, sky_.image.view, irradiance_.level[0], push, irradiance_size, 6);
            }
            {
                auto scope = vkt::GpuScope(&timer, cmd, 0, "specular");
                for (uint32_t level = 0; level < specular_levels; ++level) {
                    // Level 0 is a mirror: every half vector is n, one sample is all.
                    push.samples = level == 0 ? 1 : specular_samples;
                    push.roughness = float(level) / float(specular_levels - 1);
                    dispatch(cmd, 3, sky_.image.view, specular_.level[level], push,
                             specular_size >> level, 6);
                }
            }
            {
                auto scope = vkt::GpuScope(&timer, cmd, 0, "BRDF table");
                push.samples = lut_samples;
                dispatch(cmd, 4, VK_NULL_HANDLE, lut_.view, push, lut_size, 1);
            }
            // Compute writes to the scene pass's sampled reads, in the layout
            // it samples them in.
            for (VkImage image : images)
                vkt::image_barrier(
                    cmd, image, all, VK_IMAGE_LAYOUT_GENERAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
            timer.end(cmd, 0);
        });
        timer.collect(0);
        report(timer);
    }

    // What the start-up cost, in GPU time (timestamps), where the queue has them.
    static void report(const vkt::GpuTimer& timer) {
        if (!timer || timer.samples_ms().empty()) {
            std::fprintf(stderr, "23_materials: image-based light made (no GPU timestamps)\n");
            return;
        }
        std::string parts;
        for (const vkt::GpuTimer::Scope& scope : timer.scopes()) {
            char part[64];
            std::snprintf(part, sizeof part, "%s%s %.2f", parts.empty() ? "" : ", ",
                          scope.name.c_str(), scope.samples.at(0));
            parts += part;
        }
        std::fprintf(stderr, "23_materials: image-based light made in %.2f ms of GPU time (%s)\n",
                     timer.samples_ms()[0], parts.c_str());
    }

    vkt::Gpu gpu_;
    CubeMap sky_, irradiance_, specular_;
    vkt::Image lut_;
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout step_layout_, scene_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet scene_set_ = VK_NULL_HANDLE;
    vkt::PipelineLayout pipeline_layout_;
    std::vector<vkt::Pipeline> pipelines_;  // sky, downsample, irradiance, prefilter, table
    vkt::Pipeline background_;
};
