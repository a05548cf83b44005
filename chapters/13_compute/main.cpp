// Chapter 13: compute.
//
// A spiral galaxy of particles (65,536 by default, 16,777,216 and more where
// memory allows) orbiting a central mass. The GPU does everything: a compute
// shader writes each particle's first state from a hash of its index, a
// compute shader moves every particle by fixed steps of 1/120 s each frame,
// and the graphics pipeline draws the same buffer as a list of points.
//
// The new ideas: a storage buffer (read and written by shaders), a compute
// pipeline, workgroups and the dispatch arithmetic that covers n particles
// with them, splitting a dispatch where the device's limits say so, and the
// synchronization2 barriers between the compute writes and the vertex reads
// of the same buffer, in this frame and the next.

#include "particle.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/camera_math.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

// [workgroup-size]
// Invocations per workgroup, given to both compute shaders as specialization
// constant 0 (their local_size_x).
constexpr uint32_t kWorkgroupSize = 256;
// [/workgroup-size]

// The fixed step, as in chapter 14: 120 steps per simulated second, at most 8
// per frame (a slow machine slows the galaxy down rather than fall behind).
constexpr double kStepsPerSecond = 120.0;
constexpr uint64_t kMaxStepsPerFrame = 8;

// The mirror of `Push` in particles.glsl: 16 bytes.
struct ComputePush {
    uint32_t first;
    uint32_t count;
    uint32_t steps;
    float dt;
};

std::string mib(uint64_t bytes, bool round_up) {
    const uint64_t m = uint64_t{1024} * 1024;
    return std::to_string(round_up ? (bytes + m - 1) / m : bytes / m) + " MiB";
}

// [memory-limits]
// All the particles live in one buffer, so its size must be within three
// limits: the largest buffer (maxBufferSize), the largest single allocation
// (maxMemoryAllocationSize) and the device-local heap itself. A count beyond
// one of them is refused here with the limit's name, before anything is
// allocated. (maxStorageBufferRange limits only what one descriptor sees; the
// dispatches are split below so that it never limits --count.)
void check_memory_limits(VkPhysicalDevice physical, uint64_t count) {
    VkPhysicalDeviceVulkan13Properties properties13{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_PROPERTIES};
    VkPhysicalDeviceVulkan11Properties properties11{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES, .pNext = &properties13};
    VkPhysicalDeviceProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                           .pNext = &properties11};
    vkGetPhysicalDeviceProperties2(physical, &properties);
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    const uint32_t type = vkt::find_memory_type(physical, ~0u, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    const struct {
        const char* name;
        VkDeviceSize value;
    } limits[] = {
        {"maxBufferSize", properties13.maxBufferSize},
        {"maxMemoryAllocationSize", properties11.maxMemoryAllocationSize},
        {"device-local heap size", memory.memoryHeaps[memory.memoryTypes[type].heapIndex].size},
    };
    const uint64_t bytes = count * sizeof(Particle);
    for (const auto& limit : limits)
        if (bytes > limit.value)
            throw vkt::Error("--count " + std::to_string(count) + " needs " + mib(bytes, true) +
                             " of particles (" + std::to_string(sizeof(Particle)) +
                             " bytes each) in one buffer, more than this device's " + limit.name +
                             " of " + mib(limit.value, false));
}
// [/memory-limits]

// [barrier]
// One synchronization2 barrier on the whole particle buffer: the work of
// src_stage before it, and the memory it wrote (src_access), must be done and
// visible before dst_stage after it may do dst_access. (vkt::buffer_barrier in
// vkt/resources/compute.hpp is this function, kept for later chapters.)
void particle_barrier(VkCommandBuffer cmd, VkBuffer buffer, VkPipelineStageFlags2 src_stage,
                      VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                      VkAccessFlags2 dst_access) {
    VkBufferMemoryBarrier2 barrier{
        .sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
        .srcStageMask = src_stage,
        .srcAccessMask = src_access,
        .dstStageMask = dst_stage,
        .dstAccessMask = dst_access,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,  // no change of queue family
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .buffer = buffer,
        .offset = 0,
        .size = VK_WHOLE_SIZE,
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .bufferMemoryBarrierCount = 1,
        .pBufferMemoryBarriers = &barrier,
    };
    vkCmdPipelineBarrier2(cmd, &dependency);
}
// [/barrier]

class Galaxy : public vkt::Renderer {
public:
    explicit Galaxy(const vkt::Context& context) : device_(context.device) {
        const auto& options = context.options;
        const VkPhysicalDeviceLimits& limits = context.properties.limits;
        count_ = uint64_t(options.integer("--count"));

        if (kWorkgroupSize > limits.maxComputeWorkGroupSize[0] ||
            kWorkgroupSize > limits.maxComputeWorkGroupInvocations)
            throw vkt::Error("this chapter's workgroups of " + std::to_string(kWorkgroupSize) +
                             " exceed the device's maxComputeWorkGroupSize[0] (" +
                             std::to_string(limits.maxComputeWorkGroupSize[0]) +
                             ") or maxComputeWorkGroupInvocations (" +
                             std::to_string(limits.maxComputeWorkGroupInvocations) + ")");
        check_memory_limits(context.physical, count_);

        // [chunks]
        // One dispatch may cover at most maxComputeWorkGroupCount[0] workgroups
        // and see at most maxStorageBufferRange bytes through its descriptor:
        // on lavapipe 65,535 x 256 and 128 MiB, that is 4,194,304 particles.
        // Beyond that the particles are split into chunks, one dispatch and one
        // descriptor set each. --dispatch-max lowers the limit (the tests use
        // it to show that the split changes nothing in the picture).
        uint64_t per_dispatch =
            vkt::max_items_per_dispatch(limits, kWorkgroupSize, sizeof(Particle));
        if (options.has("--dispatch-max"))
            per_dispatch = std::min(per_dispatch, uint64_t(options.integer("--dispatch-max")) /
                                                      kWorkgroupSize * kWorkgroupSize);
        chunks_ = vkt::split_dispatch(count_, kWorkgroupSize, per_dispatch);
        // [/chunks]
        uint64_t invocations = 0;
        for (const auto& chunk : chunks_) invocations += uint64_t(chunk.groups) * kWorkgroupSize;
        std::fprintf(stderr,
                     "13_compute: %llu particles (%s), workgroups of %u: %llu invocations in %zu "
                     "dispatch(es) of up to %llu particles, %llu idle; step 1/%g s\n",
                     (unsigned long long)count_, mib(count_ * sizeof(Particle), true).c_str(),
                     kWorkgroupSize, (unsigned long long)invocations, chunks_.size(),
                     (unsigned long long)per_dispatch, (unsigned long long)(invocations - count_),
                     kStepsPerSecond);

        // [storage-buffer]
        // One buffer, two uses: the compute shaders read and write it as a
        // STORAGE_BUFFER, the vertex stage reads it as a VERTEX_BUFFER. Only
        // the GPU touches it, so it lives in device-local memory and needs no
        // staging; and there is one, not one per frame in flight (see record).
        particles_ = vkt::create_buffer(
            context.physical, device_, count_ * sizeof(Particle),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
            VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        // [/storage-buffer]

        // [descriptors]
        // The compute shaders' one binding: a storage buffer. Each chunk gets
        // a set that sees its own window of the buffer (offset, range), which
        // the shader indexes from 0; the windows are whole workgroups apart,
        // so each offset is a multiple of minStorageBufferOffsetAlignment.
        const VkDescriptorSetLayoutBinding binding{
            .binding = 0,
            .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
            .descriptorCount = 1,
            .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT,
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, {&binding, 1});
        const auto sets = uint32_t(chunks_.size());
        const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sets};
        pool_ = vkt::create_descriptor_pool(device_, sets, {&pool_size, 1});
        for (const auto& chunk : chunks_) {
            sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, set_layout_));
            vkt::write_buffer_descriptor(
                device_, sets_.back(), 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, particles_.buffer,
                chunk.first * sizeof(Particle), chunk.count * sizeof(Particle));
        }
        // [/descriptors]

        const VkPushConstantRange compute_push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(ComputePush)};
        const VkDescriptorSetLayout set_layout = set_layout_;
        compute_layout_ =
            vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&compute_push, 1});

        // [compute-pipeline]
        // A compute pipeline is one shader stage and a layout: no vertex
        // input, no rasterizer, no attachments. The workgroup size goes in as
        // specialization constant 0, read by `local_size_x_id = 0`.
        const VkSpecializationMapEntry size_entry{
            .constantID = 0, .offset = 0, .size = sizeof(uint32_t)};
        const VkSpecializationInfo specialization{
            .mapEntryCount = 1,
            .pMapEntries = &size_entry,
            .dataSize = sizeof(kWorkgroupSize),
            .pData = &kWorkgroupSize,
        };
        auto compute_pipeline = [&](const char* file) {
            vkt::ShaderModule shader = vkt::load_shader(device_, context.chapter, file);
            VkComputePipelineCreateInfo info{
                .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
                .stage =
                    {
                        .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                        .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                        .module = shader,
                        .pName = "main",
                        .pSpecializationInfo = &specialization,
                    },
                .layout = compute_layout_,
            };
            VkPipeline pipeline;
            VKT_CHECK(
                vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
            return vkt::Pipeline(device_, pipeline);
        };
        init_pipeline_ = compute_pipeline("init.comp");
        simulate_pipeline_ = compute_pipeline("simulate.comp");
        // [/compute-pipeline]

        // [draw-pipeline]
        // The draw reads the same buffer as vertex input: one vertex per
        // particle, 32 bytes apart, of which it takes the first vec4.
        const VkVertexInputBindingDescription vertex_binding{
            .binding = 0, .stride = sizeof(Particle), .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription position{.location = 0,
                                                         .binding = 0,
                                                         .format = VK_FORMAT_R32G32B32A32_SFLOAT,
                                                         .offset = offsetof(Particle, position)};
        const VkPushConstantRange draw_push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        draw_layout_ = vkt::create_pipeline_layout(device_, {}, {&draw_push, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "particle.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "particle.frag");
        draw_pipeline_ =
            vkt::create_graphics_pipeline(device_, {
                                                       .vertex = vertex,
                                                       .fragment = fragment,
                                                       .layout = draw_layout_,
                                                       .bindings = {&vertex_binding, 1},
                                                       .attributes = {&position, 1},
                                                       .topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST,
                                                       .color_formats = {context.color_format},
                                                       .alpha_blend = true,
                                                   });
        // [/draw-pipeline]
    }

    void record(const vkt::Frame& frame) override {
        // [fixed-step]
        // Headless, time is frame index / 60: exactly 2 steps per frame, so
        // frame N always shows the galaxy after the same 2N steps.
        const auto due = uint64_t(std::floor(frame.time * kStepsPerSecond + 1e-6));
        if (due > steps_done_ + kMaxStepsPerFrame) steps_done_ = due - kMaxStepsPerFrame;
        const auto steps = uint32_t(due - steps_done_);
        steps_done_ = due;
        // [/fixed-step]

        // [war-barrier]
        // Before this frame writes the particles, the previous frame must be
        // done with them: its draw read them as vertices (write-after-read:
        // waiting for VERTEX_ATTRIBUTE_INPUT is enough, a read leaves nothing
        // to make visible) and its simulate wrote them (read- and
        // write-after-write: that write must be made visible to this one).
        particle_barrier(
            frame.cmd, particles_.buffer,
            VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        // [/war-barrier]

        if (!initialised_) {
            // The first frame writes the starting state; simulate reads it.
            dispatch(frame.cmd, init_pipeline_, 0);
            particle_barrier(
                frame.cmd, particles_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            initialised_ = true;
        }

        {
            auto scope = frame.gpu_scope("simulate");
            dispatch(frame.cmd, simulate_pipeline_, steps);
        }

        // [compute-to-vertex]
        // The draw reads what simulate just wrote: vertex input must wait for
        // the compute shader, and its writes must be visible to vertex
        // attribute reads (read-after-write).
        particle_barrier(frame.cmd, particles_.buffer, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                         VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
        // [/compute-to-vertex]

        auto scope = frame.gpu_scope("draw");
        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const glm::mat4 view =
            glm::lookAt(glm::vec3(0.0f, 2.8f, 3.2f), glm::vec3(0.0f, -0.3f, 0.15f),
                        glm::vec3(0.0f, 1.0f, 0.0f));
        const glm::mat4 view_projection =
            vkt::vulkan_perspective(glm::radians(45.0f), aspect, 0.1f, 20.0f) * view;
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.002f, 0.002f, 0.008f, 1.0f}});
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw_pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdPushConstants(frame.cmd, draw_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0,
                           sizeof(glm::mat4), &view_projection);
        // [draw]
        const VkBuffer buffer = particles_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &buffer, &offset);
        vkCmdDraw(frame.cmd, /*vertexCount=*/uint32_t(count_), 1, 0, 0);
        // [/draw]
        vkCmdEndRendering(frame.cmd);
    }

private:
    // [dispatch]
    // Every chunk: its descriptor set (its window of the buffer), its first
    // index and size, and ceil(count / 256) workgroups. The chunks touch
    // disjoint particles, so they need no barrier between them.
    void dispatch(VkCommandBuffer cmd, VkPipeline pipeline, uint32_t steps) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        for (size_t c = 0; c < chunks_.size(); ++c) {
            const vkt::DispatchChunk& chunk = chunks_[c];
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute_layout_, 0, 1,
                                    &sets_[c], 0, nullptr);
            const ComputePush push{uint32_t(chunk.first), chunk.count, steps,
                                   float(1.0 / kStepsPerSecond)};
            vkCmdPushConstants(cmd, compute_layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push),
                               &push);
            vkCmdDispatch(cmd, /*groupCountX=*/chunk.groups, 1, 1);
        }
    }
    // [/dispatch]

    VkDevice device_;
    uint64_t count_ = 0;
    std::vector<vkt::DispatchChunk> chunks_;
    uint64_t steps_done_ = 0;
    bool initialised_ = false;
    vkt::Buffer particles_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;  // freed with the pool
    vkt::PipelineLayout compute_layout_;
    vkt::Pipeline init_pipeline_;
    vkt::Pipeline simulate_pipeline_;
    vkt::PipelineLayout draw_layout_;
    vkt::Pipeline draw_pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "13_compute", .title = "13 - compute"};
    // The workgroup size as a specialization constant (local_size_x_id)
    // compiles, for SPIR-V 1.6, to the LocalSizeId execution mode, which
    // needs maintenance4 (a feature every Vulkan 1.3 device has).
    spec.requirements.features = {VKT_FEATURE_13(maintenance4)};
    spec.options = {
        // 2^28 particles are 8 GiB: the devices' memory limits (checked in
        // check_memory_limits) refuse a count sooner on most machines.
        {.name = "--count",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many particles",
         .default_value = "65536",
         .min = 1,
         .max = 268435456},
        {.name = "--dispatch-max",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "at most N particles per dispatch (whole workgroups of 256)",
         .min = kWorkgroupSize,
         .max = 268435456},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Galaxy>(context);
    });
}
