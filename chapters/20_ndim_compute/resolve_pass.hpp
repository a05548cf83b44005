#pragma once
// Chapter 20's end of a compute-rasterised frame where the runner gives the
// colour target a storage view (Frame::target_storage): one compute pass,
// resolve.comp, stores every word of the pixel buffer into the target and
// writes the background back into the buffer for the next frame. It replaces
// the fill and the copy of compute_raster.hpp, two passes that on a GPU built
// for compute run on its slower transfer side.

#include "vkt/core/barrier.hpp"
#include "vkt/core/device.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"

#include <vector>

namespace ch20 {

class ResolvePass {
public:
    // The shader stores to an image declared without a format (so one
    // shader serves RGBA and BGRA targets), which needs the device feature
    // and, for Vulkan 1.3, the storage view's format to allow it.
    static bool available(const vkt::Context& context) {
        if (context.storage_format == VK_FORMAT_UNDEFINED ||
            !context.features.has(VKT_FEATURE_10(shaderStorageImageWriteWithoutFormat)))
            return false;
        VkFormatProperties3 features{.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
        VkFormatProperties2 properties{.sType = VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2,
                                       .pNext = &features};
        vkGetPhysicalDeviceFormatProperties2(context.physical, context.storage_format, &properties);
        return (features.optimalTilingFeatures &
                VK_FORMAT_FEATURE_2_STORAGE_WRITE_WITHOUT_FORMAT_BIT) != 0;
    }

    // Its own set per frame in flight: 0 the pixel buffer (pointed at when
    // the buffer is made, use_pixels), 1 the target's storage view, pointed
    // at each frame (the runner may have made a new target since this
    // slot's last frame, and a new view may even reuse the old one's handle,
    // so comparing handles cannot tell). BGRA, a specialization constant,
    // says which way round the view's components lie.
    explicit ResolvePass(const vkt::Context& context) : device_(context.device) {
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}};
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, context.frames_in_flight},
            {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, context.frames_in_flight}};
        pool_ = vkt::create_descriptor_pool(device_, context.frames_in_flight, sizes);
        for (uint32_t i = 0; i < context.frames_in_flight; ++i)
            sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, set_layout_));
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
        const VkDescriptorSetLayout set_layout = set_layout_;
        layout_ = vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&push, 1});
        const VkBool32 bgra = context.storage_format == VK_FORMAT_B8G8R8A8_UNORM;
        const VkSpecializationMapEntry entry{0, 0, sizeof(VkBool32)};
        const VkSpecializationInfo specialization{1, &entry, sizeof bgra, &bgra};
        vkt::ShaderModule shader = vkt::load_shader(device_, context.chapter, "resolve.comp");
        pipeline_ = vkt::create_compute_pipeline(device_, shader, layout_, &specialization);
    }

    // The pixel buffer, in every frame's set: when ComputeRaster makes it
    // (at start-up and with the window's size, when no frame is in flight).
    void use_pixels(VkBuffer pixels) const {
        for (VkDescriptorSet set : sets_)
            vkt::write_buffer_descriptor(device_, set, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, pixels,
                                         0, VK_WHOLE_SIZE);
    }

    // [resolve-record]
    // After the rasteriser's writes to the pixel buffer: the target, handed
    // over untouched, to GENERAL (its old contents do not matter), and one
    // invocation per pixel. The target stays in GENERAL: the runner's next
    // barrier starts there (target_after). The buffer's background is for the next
    // frame's rasteriser, which waits for this pass (ComputeRaster::clear).
    void record(const vkt::Frame& frame, VkBuffer pixels, uint32_t background) const {
        const VkDescriptorSet set = sets_[frame.slot];  // its last frame is finished
        vkt::write_storage_image_descriptor(device_, set, 1, frame.target_storage);

        const VkCommandBuffer cmd = frame.cmd;
        vkt::buffer_barrier(
            cmd, pixels, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkt::image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                           frame.target_ready, VK_ACCESS_2_NONE,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        const Push push{{frame.extent.width, frame.extent.height}, background};
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(frame.extent.width, side)),
                      uint32_t(vkt::dispatch_count(frame.extent.height, side)), 1);
    }
    // [/resolve-record]

private:
    static constexpr uint32_t side = 16;  // resolve.comp's workgroup: 16 x 16 pixels
    struct Push {                         // resolve.comp's push constants
        uint32_t size[2];
        uint32_t background;
    };

    VkDevice device_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;  // [slot]
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace ch20
