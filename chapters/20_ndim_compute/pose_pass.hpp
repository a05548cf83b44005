#pragma once
// Chapter 20's poses, built on the GPU (pose.comp). What each object does over
// time, its start angles, spins, scale and position, is uploaded once; each
// frame the CPU writes only what the keys changed (an angle per plane and an
// offset per axis, the same for every object) and the time, and one dispatch
// builds every object's n x n matrix and position into the poses buffer that
// the transform pass reads. The pass has its own set and pipeline layout.

#include "layouts.hpp"
#include "vkt/domains/ndim.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/ndim_controls.hpp"

#include <cstring>
#include <vector>

namespace ch20 {

class PosePass {
public:
    enum Binding : uint32_t { motions_binding, steer_binding, poses_binding, binding_count };

    // `poses`: the transform pass's, one per frame in flight.
    PosePass(const vkt::Context& context, const nd::Scene& scene, std::span<const VkBuffer> poses)
        : gpu_(context.gpu()),
          n_(scene.dim),
          objects_(uint32_t(scene.objects.size())),
          poses_(poses.begin(), poses.end()) {
        const VkDevice device = gpu_.device;
        // [motions]
        // Once: per object its start angles, spins, scale and position.
        std::vector<float> motions;
        for (const nd::SceneObject& object : scene.objects)
            for (const std::vector<float>* part :
                 {&object.start.angles, &object.spin, &object.start.scale, &object.start.position})
                motions.insert(motions.end(), part->begin(), part->end());
        motions_ = vkt::create_device_buffer(gpu_, motions.data(), motions.size() * sizeof(float),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        // [/motions]
        set_layout_ = storage_set_layout(device, binding_count);
        pool_ = storage_pool(device, uint32_t(poses_.size()), binding_count);
        const VkDeviceSize steer_bytes = VkDeviceSize(nd::plane_count(n_) + n_) * sizeof(float);
        for (VkBuffer pose_buffer : poses_) {
            steer_.push_back(
                vkt::create_host_buffer(gpu_, steer_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            const VkDescriptorSet set = vkt::allocate_descriptor_set(device, pool_, set_layout_);
            const VkBuffer buffers[] = {motions_.buffer, steer_.back().buffer, pose_buffer};
            for (uint32_t b = 0; b < binding_count; ++b)
                vkt::write_buffer_descriptor(device, set, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             buffers[b], 0, VK_WHOLE_SIZE);
            sets_.push_back(set);
        }
        const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(float)};
        const VkDescriptorSetLayout set_layout = set_layout_;
        layout_ = vkt::create_pipeline_layout(device, {&set_layout, 1}, {&range, 1});
        const VkSpecializationMapEntry entry{0, 0, sizeof(int32_t)};
        const int32_t n = n_;
        const VkSpecializationInfo specialization{1, &entry, sizeof n, &n};
        pipeline_ = vkt::create_compute_pipeline(
            device, vkt::load_shader(device, context.chapter, "pose.comp"), layout_,
            &specialization);
    }

    // [pose-record]
    // The CPU's share each frame: the keys' angles and offsets, P + n floats.
    // Then the dispatch, between a barrier that waits for the last reader of
    // this slot's poses (the transform pass of the frame that used the slot
    // before) and one that makes the new poses visible to this frame's.
    void record(VkCommandBuffer cmd, uint32_t slot, float time, const nd::Controls& keys) const {
        auto* steer = static_cast<float*>(steer_[slot].mapped);
        std::memcpy(steer, keys.angles.data(), keys.angles.size() * sizeof(float));
        std::memcpy(steer + keys.angles.size(), keys.offset.data(),
                    keys.offset.size() * sizeof(float));
        constexpr auto compute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
        vkt::buffer_barrier(cmd, poses_[slot], compute, VK_ACCESS_2_NONE, compute,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[slot], 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof time, &time);
        vkCmdDispatch(cmd, objects_, 1, 1);  // a workgroup per object
        vkt::buffer_barrier(cmd, poses_[slot], compute, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            compute, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    }
    // [/pose-record]

private:
    vkt::Gpu gpu_;
    int n_;
    uint32_t objects_;
    std::vector<VkBuffer> poses_;     // [slot], the transform pass's
    vkt::Buffer motions_;             // [object], uploaded once
    std::vector<vkt::Buffer> steer_;  // [slot], host-visible
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;  // [slot]
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace ch20
