#pragma once
// Chapter 28's --path task: the same field drawn by chapter 26's task and
// mesh shaders. A task workgroup tests 32 instances, as the cull pass does
// (instance_cull.glsl), and launches one mesh workgroup for each meshlet of
// each instance it keeps: the cull and the draw in one command, with no
// draw list in between. With --meshlet-cull on (the default there) it
// first tests each of those meshlets and launches only the survivors
// (meshlet_cull.glsl), which the cull pass, one draw per instance, cannot
// do. The meshlets and the mesh pipeline are chapter 26's,
// from common/ (vkt/scene/meshlets.hpp, vkt/resources/mesh_pipeline.hpp).

#include "draw_pass.hpp"
#include "scene.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/device.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/mesh_pipeline.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/meshlets.hpp"

#include "vkt/frame/args.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace ch28 {

// What task_data.glsl and instances.mesh declare: 32 instances a task
// workgroup, at most 16 meshlets a mesh, 64 vertices and 124 triangles a
// meshlet (chapter 26's), a launch packed as instance << 12 | meshlet.
constexpr uint32_t kTaskGroup = 32, kMostMeshlets = 16, kMeshletBits = 12;
constexpr uint32_t kMeshVertices = 64, kMeshTriangles = 124, kMeshWorkgroup = 32;
constexpr uint32_t kFates = 2;  // Push::phase of --view culled's pass (task_data.glsl)

// [device]
// --path task asks for VK_EXT_mesh_shader and its two features; only then
// (a device without them still runs the indirect path).
inline void require_mesh_shaders(vkt::DeviceRequirements& requirements) {
    static VkPhysicalDeviceMeshShaderFeaturesEXT mesh_features{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT,
        .taskShader = VK_TRUE,
        .meshShader = VK_TRUE,
    };
    requirements.extensions.push_back(VK_EXT_MESH_SHADER_EXTENSION_NAME);
    requirements.extension_features = &mesh_features;
}
// [/device]

// [option]
// --meshlet-cull on|off: the task path's alone (on unless given).
inline vkt::OptionSpec meshlet_cull_option() {
    return {.name = "--meshlet-cull",
            .type = vkt::OptionType::choice,
            .help = "--path task: test each meshlet of a kept instance (on) or launch all (off)",
            .choices = {"on", "off"}};
}
inline bool meshlet_cull(const vkt::Options& options) {
    if (options.has("--meshlet-cull") && options.text("--path") != "task")
        throw vkt::UsageError(
            "--meshlet-cull needs --path task: the indirect path draws "
            "whole instances, one command each, and has no meshlets");
    if (options.text("--view") == "culled" && options.has("--meshlet-cull") &&
        options.text("--meshlet-cull") == "off")
        throw vkt::UsageError(
            "--view culled with --path task shows what the meshlet tests cull: "
            "it needs --meshlet-cull on");
    return !options.has("--meshlet-cull") || options.text("--meshlet-cull") == "on";
}
// [/option]

// [meshlets]
// Each mesh but the floor (which the vertex pipeline draws in both paths)
// cut into meshlets, one list for all: a mesh's are first_meshlet ..
// first_meshlet + meshlet_count - 1, their vertices indices into the shared
// vertex buffer.
inline vkt::Meshlets make_meshlets(const vkt::shapes::MeshBuilder& builder,
                                   std::vector<Mesh>& meshes) {
    std::vector<glm::vec3> positions;
    positions.reserve(builder.vertices.size());
    for (const vkt::shapes::Vertex& v : builder.vertices) positions.push_back(v.position);
    vkt::Meshlets all;
    for (uint32_t kind = 0; kind < floor_mesh; ++kind) {
        const vkt::shapes::MeshRange range = meshes[kind].range;
        const std::vector<uint32_t> indices(
            builder.indices.begin() + range.first_index,
            builder.indices.begin() + range.first_index + range.index_count);
        vkt::Meshlets one = vkt::build_meshlets(positions, indices, kMeshVertices, kMeshTriangles);
        meshes[kind].first_meshlet = uint32_t(all.meshlets.size());
        meshes[kind].meshlet_count = uint32_t(one.meshlets.size());
        if (one.meshlets.size() > kMostMeshlets)
            throw vkt::Error("mesh " + std::to_string(kind) + " makes " +
                             std::to_string(one.meshlets.size()) + " meshlets, more than the " +
                             std::to_string(kMostMeshlets) + " a task payload holds");
        for (vkt::Meshlet m : one.meshlets) {
            m.vertex_offset += uint32_t(all.vertices.size());
            m.triangle_offset += uint32_t(all.triangles.size());
            all.meshlets.push_back(m);
        }
        all.vertices.insert(all.vertices.end(), one.vertices.begin(), one.vertices.end());
        all.triangles.insert(all.triangles.end(), one.triangles.begin(), one.triangles.end());
    }
    return all;
}
// [/meshlets]

class TaskPath {
public:
    TaskPath(const vkt::Gpu& gpu, std::string_view chapter, const vkt::shapes::MeshBuilder& builder,
             const vkt::Meshlets& meshlets, VkDescriptorSetLayout culling_set,
             VkShaderStageFlags stages, VkFormat colour_format, VkFormat depth_format,
             bool cull_meshlets, bool fates)
        : stages_(stages), meshlet_cull_(cull_meshlets), fates_(fates) {
        // The vertices again, as a storage buffer the mesh shader reads
        // (vec4s: std430 pads a vec3 array's elements to 16 bytes anyway).
        std::vector<glm::vec4> vertices;
        for (const vkt::shapes::Vertex& v : builder.vertices)
            vertices.insert(vertices.end(),
                            {glm::vec4(v.position, 1.0f), glm::vec4(v.normal, 0.0f)});
        const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        buffers_[0] =
            vkt::create_device_buffer(gpu, meshlets.meshlets.data(),
                                      meshlets.meshlets.size() * sizeof(vkt::Meshlet), storage);
        buffers_[1] = vkt::create_device_buffer(
            gpu, meshlets.vertices.data(), meshlets.vertices.size() * sizeof(uint32_t), storage);
        buffers_[2] = vkt::create_device_buffer(
            gpu, meshlets.triangles.data(), meshlets.triangles.size() * sizeof(uint32_t), storage);
        buffers_[3] = vkt::create_device_buffer(gpu, vertices.data(),
                                                vertices.size() * sizeof(glm::vec4), storage);
        const glm::vec4 tested[5] = {};  // --view culled's camera: a matrix and the eye
        buffers_[4] = vkt::create_device_buffer(gpu, tested, sizeof(tested),
                                                storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT);

        // Set 1, the meshlets (the task shader reads their bounds); set 0 is
        // the cull pass's, bound as it is.
        std::vector<VkDescriptorSetLayoutBinding> bindings;
        for (uint32_t b = 0; b < 5; ++b)
            bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT,
                                nullptr});
        set_layout_ = vkt::create_descriptor_set_layout(gpu.device, bindings);
        const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 5};
        pool_ = vkt::create_descriptor_pool(gpu.device, 1, {&size, 1});
        set_ = vkt::allocate_descriptor_set(gpu.device, pool_, set_layout_);
        for (uint32_t b = 0; b < 5; ++b)
            vkt::write_buffer_descriptor(gpu.device, set_, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                         buffers_[b].buffer, 0, VK_WHOLE_SIZE);
        const VkDescriptorSetLayout sets[] = {culling_set, set_layout_};
        const VkPushConstantRange push{stages_, 0, sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(gpu.device, sets, {&push, 1});

        vkt::ShaderModule task = vkt::load_shader(gpu.device, chapter, "instances.task");
        vkt::ShaderModule mesh = vkt::load_shader(gpu.device, chapter, "instances.mesh");
        vkt::ShaderModule fragment = vkt::load_shader(gpu.device, chapter, "draw.frag");
        pipeline_ =
            vkt::create_mesh_pipeline(gpu.device, layout_, task, mesh, kMeshWorkgroup, fragment,
                                      colour_format, depth_format, VK_COMPARE_OP_GREATER);
        draw_mesh_tasks_ = reinterpret_cast<PFN_vkCmdDrawMeshTasksEXT>(
            vkGetDeviceProcAddr(gpu.device, "vkCmdDrawMeshTasksEXT"));
        if (!draw_mesh_tasks_)
            throw vkt::Error("vkGetDeviceProcAddr(vkCmdDrawMeshTasksEXT) failed");
    }

    // [task-draw]
    // Inside the pass's rendering, set 0 bound: one task workgroup per 32
    // instances; the mesh workgroups they launch draw. The normal cones need
    // the eye: the point the matrix sends to clip (0, 0, z, 0), found by
    // inverting it in double precision.
    static glm::vec3 eye_of(const glm::mat4& clip_from_world) {
        const glm::dvec4 eye = glm::inverse(glm::dmat4(clip_from_world)) * glm::dvec4(0, 0, 1, 0);
        return glm::vec3(glm::dvec3(eye) / eye.w);
    }
    void draw(VkCommandBuffer cmd, Push push) const {
        push.eye = eye_of(push.clip_from_world);
        push.meshlet_cull = meshlet_cull_ ? 1u : 0u;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 1, 1, &set_, 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout_, stages_, 0, sizeof(Push), &push);
        draw_mesh_tasks_(cmd, uint32_t(vkt::dispatch_count(push.instance_count, kTaskGroup)), 1, 1);
    }
    // [/task-draw]

    // [before-fates]
    // --view culled: after the frame's two passes, one more from a second
    // camera (main.cpp, scene.hpp) launches every meshlet and colours it by
    // the tests made for the first, whose matrix and eye it reads from a
    // buffer (the push constants hold the second camera's). The two passes' colour
    // and depth writes come before this pass clears them.
    bool shows_fates() const { return fates_; }
    void before_fates(VkCommandBuffer cmd, const Push& push) const {
        const glm::vec4 tested[5] = {push.clip_from_world[0], push.clip_from_world[1],
                                     push.clip_from_world[2], push.clip_from_world[3],
                                     glm::vec4(eye_of(push.clip_from_world), 1.0f)};
        vkt::memory_barrier(cmd, VK_PIPELINE_STAGE_2_TASK_SHADER_BIT_EXT, 0,
                            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0);  // the passes' reads
        vkCmdUpdateBuffer(cmd, buffers_[4].buffer, 0, sizeof(tested), tested);
        vkt::memory_barrier(
            cmd,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_TASK_SHADER_BIT_EXT |
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT |
                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    }
    // [/before-fates]

    // [report]
    // After the last frame: the meshlets of the drawn instances, and those
    // launched; the rest were culled, for one of three reasons.
    void report(const uint32_t* counts) const {
        std::fprintf(stderr,
                     "28_gpu_culling: last frame: --meshlet-cull %s: %u meshlets of the drawn "
                     "instances, %u launched; %u culled: %u outside the frustum, %u facing away, "
                     "%u occluded\n",
                     meshlet_cull_ ? "on" : "off", counts[5], counts[6], counts[5] - counts[6],
                     counts[7], counts[8], counts[9]);
        if (counts[6] + counts[7] + counts[8] + counts[9] != counts[5] ||
            (!meshlet_cull_ && counts[6] != counts[5]))
            throw vkt::Error("the task shader's meshlet counts do not add up");
    }
    // [/report]

private:
    VkShaderStageFlags stages_;
    bool meshlet_cull_, fates_;
    // meshlets, their vertex indices, their triangles, the vertices, the tested camera
    vkt::Buffer buffers_[5];
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
    PFN_vkCmdDrawMeshTasksEXT draw_mesh_tasks_ = nullptr;
};

}  // namespace ch28
