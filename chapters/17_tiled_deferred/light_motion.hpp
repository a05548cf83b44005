#pragma once
// Chapter 17's moving lights, on the GPU. What does not change with time (each
// light's home and path, vkt::deferred::MovingLights) is uploaded once; each
// frame one dispatch of move_lights.comp writes every light where it is now,
// into the frame's lights buffer (set 0, binding 1 of the other passes). The
// CPU records and submits; a million lights never cross the bus again.
//
// The pass has its own set: the homes, the paths, and one frame's lights.

#include "vkt/core/barrier.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/moving_lights.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ch17 {

class LightMotion {
public:
    // The bindings of move_lights.comp's set.
    enum Binding : uint32_t { homes_binding, paths_binding, lights_binding, binding_count };

    // `lights`: the frame's lights buffers, one per frame in flight.
    LightMotion(const vkt::Context& context, const vkt::deferred::MovingLights& moving,
                const std::vector<vkt::Buffer>& lights)
        : gpu_(context.gpu()), count_(moving.size()) {
        const VkDevice device = gpu_.device;
        // [upload]
        // Once: 32 bytes of home and 8 of path per light, in device-local memory.
        homes_ =
            vkt::create_device_buffer(gpu_, moving.homes().data(), count_ * sizeof(vkt::PointLight),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        paths_ = vkt::create_device_buffer(gpu_, moving.paths().data(),
                                           count_ * sizeof(vkt::deferred::MovingLights::Path),
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        // [/upload]
        VkDescriptorSetLayoutBinding bindings[binding_count];
        for (uint32_t b = 0; b < binding_count; ++b)
            bindings[b] = {b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                           nullptr};
        set_layout_ = vkt::create_descriptor_set_layout(device, bindings);
        const auto slots = uint32_t(lights.size());
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, binding_count * slots};
        pool_ = vkt::create_descriptor_pool(device, slots, {&size, 1});
        for (const vkt::Buffer& frame_lights : lights) {
            const VkDescriptorSet set = vkt::allocate_descriptor_set(device, pool_, set_layout_);
            const VkBuffer buffers[] = {homes_.buffer, paths_.buffer, frame_lights.buffer};
            for (uint32_t b = 0; b < binding_count; ++b)
                vkt::write_buffer_descriptor(device, set, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             buffers[b], 0, VK_WHOLE_SIZE);
            sets_.push_back(set);
            lights_.push_back(frame_lights.buffer);
        }
        const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
        const VkDescriptorSetLayout set_layout = set_layout_;
        layout_ = vkt::create_pipeline_layout(device, {&set_layout, 1}, {&range, 1});
        pipeline_ = vkt::create_compute_pipeline(
            device, vkt::load_shader(device, context.chapter, "move_lights.comp"), layout_);
    }

    // [record]
    // The slot's lights were last read by the passes of the frame that used
    // this slot before: the first barrier waits for them (a write after a
    // read needs no more). The second makes the new positions visible to
    // every shader that reads lights in this frame.
    void record(VkCommandBuffer cmd, uint32_t slot, float time) const {
        constexpr auto readers = VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT |
                                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        constexpr auto compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        vkt::buffer_barrier(cmd, lights_[slot], readers, VK_ACCESS_2_NONE, compute,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[slot], 0,
                                nullptr);
        const Push push{time, count_};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
        vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(count_, group)), 1, 1);
        vkt::buffer_barrier(cmd, lights_[slot], compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            readers, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    }
    // [/record]

    // [verify-motion]
    // --verify: the slot's lights moved on the GPU to `time`, read back and
    // compared with the CPU's (MovingLights::write, the same formula). Throws
    // vkt::Error when a light is further off than `tolerance` world units.
    void verify(uint32_t slot, float time, const vkt::deferred::MovingLights& moving) const {
        const VkDeviceSize bytes = VkDeviceSize{count_} * sizeof(vkt::PointLight);
        vkt::Buffer host = vkt::create_host_buffer(gpu_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            record(cmd, slot, time);
            vkt::buffer_barrier(cmd, lights_[slot], VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy region{0, 0, bytes};
            vkCmdCopyBuffer(cmd, lights_[slot], host.buffer, 1, &region);
            vkt::buffer_barrier(cmd, host.buffer, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                VK_ACCESS_2_HOST_READ_BIT);
        });
        std::vector<vkt::PointLight> cpu(count_);
        moving.write(time, cpu.data());
        const auto* gpu = static_cast<const vkt::PointLight*>(host.mapped);
        float position = 0.0f;
        bool rest_equal = true;  // radius, colour and intensity are copied, not computed
        for (uint32_t i = 0; i < count_; ++i) {
            const glm::vec3 d = gpu[i].position - cpu[i].position;
            position = std::max({position, std::abs(d.x), std::abs(d.y), std::abs(d.z)});
            rest_equal = rest_equal && gpu[i].radius == cpu[i].radius &&
                         gpu[i].colour == cpu[i].colour && gpu[i].intensity == cpu[i].intensity;
        }
        constexpr float tolerance = 1e-5f;  // world units; the scene is 12 across
        std::fprintf(stderr,
                     "17_tiled_deferred: verify motion: %u lights at t = %g, largest position "
                     "difference from the CPU %g (tolerance %g)%s\n",
                     count_, double(time), double(position), double(tolerance),
                     rest_equal ? "" : "; radius, colour or intensity differ");
        if (!(position <= tolerance) || !rest_equal)
            throw vkt::Error("--verify: the GPU's moving lights differ from the CPU's");
    }
    // [/verify-motion]

private:
    struct Push {  // MovePush in move_lights.comp
        float time;
        uint32_t count;
    };
    static constexpr uint32_t group = 256;  // local_size_x of move_lights.comp

    vkt::Gpu gpu_;
    uint32_t count_;
    vkt::Buffer homes_, paths_;  // [light], uploaded once
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
    std::vector<VkDescriptorSet> sets_;  // [slot]
    std::vector<VkBuffer> lights_;       // [slot], the frame's lights
};

}  // namespace ch17
