#pragma once
// Chapter 20's second way to draw the lines (--raster compute): a compute
// pass that rasterises every line into a storage buffer of one word per
// pixel (raster.comp: one invocation per line, atomicMax per pixel), laid
// out as the colour target's pixels, and a copy that moves it onto the
// colour target, or, where the target has a storage view, a compute pass
// that stores it there (resolve_pass.hpp). The binned rasteriser
// (binned_raster.hpp) draws into the same buffer with the same palette. It
// owns set 1 of the chapter's layout (layouts.hpp): the line ends (the
// transform pass's index buffer), the pixels and the palette; the projected
// vertices it reads through the transform pass's set 0.

#include "layouts.hpp"
#include "resolve_pass.hpp"
#include "scene_state.hpp"

#include "tuning.hpp"
#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ch20 {

class ComputeRaster {
public:
    enum Binding : uint32_t { ends_binding, pixels_binding, palette_binding, binding_count };

    // [raster-pipeline]
    // The rasteriser writes the target's own pixel layout, so the palette
    // (raster.comp) is built in the target's byte order. The set points at
    // the line ends and the palette here, at the pixels in resize.
    ComputeRaster(const vkt::Context& context, const Tuning& tuning, const Layouts& layouts,
                  VkBuffer ends, uint32_t line_total)
        : gpu_(context.gpu()),
          device_(context.device),
          layout_(layouts.pipeline),
          line_total_(line_total) {
        if (context.color_format != VK_FORMAT_B8G8R8A8_SRGB &&
            context.color_format != VK_FORMAT_R8G8B8A8_SRGB)
            throw vkt::Error(
                "--raster compute: the colour target is neither "
                "B8G8R8A8_SRGB nor R8G8B8A8_SRGB");
        const bool bgra = context.color_format == VK_FORMAT_B8G8R8A8_SRGB;
        const std::vector<uint32_t> words = palette(bgra);
        palette_ = vkt::create_device_buffer(gpu_, words.data(), words.size() * sizeof(uint32_t),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        pool_ = storage_pool(device_, 1, binding_count);
        set_ = vkt::allocate_descriptor_set(device_, pool_, layouts.raster);
        vkt::write_buffer_descriptor(device_, set_, ends_binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                     ends, 0, VK_WHOLE_SIZE);
        vkt::write_buffer_descriptor(device_, set_, palette_binding,
                                     VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, palette_.buffer, 0,
                                     VK_WHOLE_SIZE);
        // The background, as the target stores it: (0.006, 0.006, 0.012)
        // sRGB-encoded is (18, 18, 29), level 0 below every line's.
        background_ = bgra ? 29u | 18u << 8 | 18u << 16 : 18u | 18u << 8 | 29u << 16;
        // [lanes]
        // Invocations per line, 1 (250 n-cubes) to 32 (one 4-cube): as many
        // as keep the launch near the tuning's count (a few per core of a
        // GPU; on a CPU device only enough to keep its cores busy, since more
        // lanes per line there only add each invocation's set-up).
        lanes_ = 1;
        while (lanes_ < 32 && uint64_t(line_total_) * lanes_ * 2 <= tuning.raster_invocations)
            lanes_ *= 2;
        // [/lanes]
        // raster.comp's LANES (id 0) and LOOK_FIRST (id 1), laid out by offsetof.
        struct Constants {
            int32_t lanes;
            VkBool32 look_first;
        } constants{lanes_, line_total_ >= tuning.raster_look_from_lines ? VK_TRUE : VK_FALSE};
        const VkSpecializationMapEntry entries[] = {
            {0, offsetof(Constants, lanes), sizeof(Constants::lanes)},
            {1, offsetof(Constants, look_first), sizeof(Constants::look_first)}};
        const VkSpecializationInfo specialization{.mapEntryCount = 2,
                                                  .pMapEntries = entries,
                                                  .dataSize = sizeof(Constants),
                                                  .pData = &constants};
        vkt::ShaderModule raster = vkt::load_shader(device_, context.chapter, "raster.comp");
        pipeline_ = vkt::create_compute_pipeline(device_, raster, layout_, &specialization);
        max_groups_x_ = context.properties.limits.maxComputeWorkGroupCount[0];
        max_storage_range_ = context.properties.limits.maxStorageBufferRange;
        // The resolve pass where the runner gives the target a storage view
        // and the device can store to it; by default where the tuning says
        // (not on a CPU device, where the copy is a memcpy while a store pass
        // converts and stores each pixel on its own).
        const std::string to_target = context.options.text("--to-target");
        if ((to_target == "store" || (to_target == "auto" && tuning.store_to_target)) &&
            ResolvePass::available(context))
            resolve_.emplace(context);
        resize(context.extent);
    }
    // [/raster-pipeline]

    // [pixel-buffer]
    // The compute rasteriser's target: one 32-bit word per pixel, row after
    // row, written with atomics (STORAGE), filled with the background
    // (TRANSFER_DST) and copied to the colour target (TRANSFER_SRC). It
    // follows the window's size, and starts out filled: the frame's first
    // rasteriser then finds the background already (clear).
    void resize(VkExtent2D extent) {
        // One descriptor sees the whole buffer, so it must fit in one
        // storage-buffer range (at least 128 MiB: 5,792x5,792 pixels).
        const VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
        if (bytes > max_storage_range_)
            throw vkt::Error("--raster compute: " + std::to_string(extent.width) + "x" +
                             std::to_string(extent.height) + " needs a pixel buffer of " +
                             std::to_string(bytes) +
                             " bytes, more than this device's maxStorageBufferRange (" +
                             std::to_string(max_storage_range_) + ")");
        pixels_ = vkt::create_buffer(gpu_.physical, device_, bytes,
                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                     VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        vkt::write_buffer_descriptor(device_, set_, pixels_binding,
                                     VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, pixels_.buffer, 0,
                                     VK_WHOLE_SIZE);
        if (resolve_) resolve_->use_pixels(pixels_.buffer);
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            vkCmdFillBuffer(cmd, pixels_.buffer, 0, VK_WHOLE_SIZE, background_);
            vkt::buffer_barrier(
                cmd, pixels_.buffer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        });
        clean_ = true;
    }
    // [/pixel-buffer]

    // [compute-raster]
    // The words filled with the background, then every line rasterised into
    // them. Where the last frame's resolve pass (or resize) left the
    // background behind, only wait for it; else fill (after the previous
    // frame's copy has read them). The transform pass has bound set 0 and
    // the push constants already (same layout); `projected` is what it wrote.
    void clear(VkCommandBuffer cmd, vkt::GpuTimer* timer = nullptr, uint32_t slot = 0) {
        const VkAccessFlags2 read_write =
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
        if (clean_) {
            vkt::buffer_barrier(cmd, pixels_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, read_write);
            clean_ = false;  // the lines are about to be drawn into it
            return;
        }
        vkt::GpuScope fill(timer, cmd, slot, "fill");
        // The specification counts vkCmdFillBuffer among the clear commands
        // (CLEAR stage); validation layers before 2024 (Debian 12's among
        // them) count it as a copy. ALL_TRANSFER covers both.
        vkt::buffer_barrier(cmd, pixels_.buffer, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdFillBuffer(cmd, pixels_.buffer, 0, VK_WHOLE_SIZE, background_);
        vkt::buffer_barrier(cmd, pixels_.buffer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            read_write);
    }
    void draw(VkCommandBuffer cmd, VkBuffer projected) {
        clear(cmd);
        vkt::buffer_barrier(cmd, projected, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
        // lanes_ invocations per line (raster.comp), the workgroups laid
        // out in rows of at most max_groups_x_.
        const uint64_t groups = vkt::dispatch_count(uint64_t(line_total_) * lanes_, group);
        const uint64_t rows = vkt::dispatch_count(groups, max_groups_x_);
        bind_set(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdDispatch(cmd, uint32_t(rows == 1 ? groups : max_groups_x_), uint32_t(rows), 1);
    }
    // [/compute-raster]

    // Set 1, for this pass and the binned rasteriser's tile pass.
    void bind_set(VkCommandBuffer cmd) const {
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 1, 1, &set_, 0,
                                nullptr);
    }

    // [copy-to-target]
    // The words are the target's pixels already: a buffer-to-image copy
    // takes the buffer's bytes as texels of the target's own format (4
    // bytes each, rows tightly packed), bits unchanged. The target comes
    // untouched (its old contents do not matter) and goes to its transfer
    // layout for the copy, where it stays: the runner's next barrier starts
    // there. (The binned rasteriser ends the same way.)
    void copy_to_target(const vkt::Frame& frame) const {
        const VkCommandBuffer cmd = frame.cmd;
        vkt::buffer_barrier(cmd, pixels_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, frame.target_ready,
                           VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                       .imageExtent = {frame.extent.width, frame.extent.height, 1}};
        vkCmdCopyBufferToImage(cmd, pixels_.buffer, frame.target,
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    }
    // [/copy-to-target]

    // [finish]
    // The frame's last pass: the resolve where this frame's target has a
    // storage view, which also leaves the background for the next frame;
    // else the copy, after which the next frame fills.
    bool resolves(const vkt::Frame& frame) const {
        return resolve_ && frame.target_storage != VK_NULL_HANDLE;
    }
    void finish(const vkt::Frame& frame) {
        if (!resolves(frame)) return copy_to_target(frame);
        resolve_->record(frame, pixels_.buffer, background_);
        clean_ = true;
    }
    // [/finish]

    VkBuffer pixels() const { return pixels_.buffer; }

private:
    vkt::Gpu gpu_;
    VkDevice device_;
    VkPipelineLayout layout_;
    uint32_t line_total_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;  // set 1
    vkt::Buffer palette_, pixels_;
    vkt::Pipeline pipeline_;
    uint32_t max_groups_x_ = 65535;       // maxComputeWorkGroupCount[0]
    uint32_t max_storage_range_ = 0;      // maxStorageBufferRange
    int lanes_ = 1;                       // raster.comp's LANES
    uint32_t background_ = 0;             // the clear value, as the target stores it
    bool clean_ = false;                  // the pixel buffer holds the background only
    std::optional<ResolvePass> resolve_;  // where the runner may give a storage view
};

}  // namespace ch20
