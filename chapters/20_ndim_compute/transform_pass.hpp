#pragma once
// Chapter 20's transform pass: every unique vertex of every object
// transformed and projected once per frame (transform.comp; with --raster
// binned transform_boxes.comp, which also merges each object's box). It owns
// the scene's buffers, built once (each mesh's coordinates, the object table,
// the line ends), and per frame in flight the poses (which the pose pass
// writes, pose_pass.hpp) and the projected vertices; set 0 of the chapter's
// layout (layouts.hpp) names them.

#include "layouts.hpp"
#include "scene_state.hpp"
#include "tuning.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace ch20 {

class TransformPass {
public:
    enum Binding : uint32_t {
        coords_binding,     // each mesh's coordinates, n floats a vertex
        objects_binding,    // ObjectInfo per object
        poses_binding,      // per object M (n x n) and p, the pose pass's
        projected_binding,  // Projected per vertex, this pass's output
        binding_count
    };

    TransformPass(const vkt::Context& context, const nd::Scene& scene, const Tuning& tuning,
                  const Layouts& layouts, bool boxes)
        : gpu_(context.gpu()), tuning_(tuning) {
        build_scene_buffers(scene);
        create_frame_buffers(context, scene);
        write_sets(layouts, context.frames_in_flight);
        create_pipeline(context, scene.dim, layouts.pipeline, boxes);
    }

    // [dispatch]
    // x runs over the largest mesh's vertices in workgroups of 128 (64 on a
    // CPU device, each invocation taking Tuning::vertices_per_lane), y the
    // objects. The set and the push constants stay bound for the passes after.
    void record(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t slot,
                const Push& push) const {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &sets_[slot], 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout, push_stages, 0, sizeof(Push), &push);
        const uint32_t per_group = tuning_.transform_group * tuning_.vertices_per_lane;
        vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(max_vertices_, per_group)), object_count_,
                      1);
    }
    // [/dispatch]

    VkBuffer projected(uint32_t slot) const { return projected_[slot].buffer; }
    std::vector<VkBuffer> poses() const {
        std::vector<VkBuffer> buffers;
        for (const vkt::Buffer& b : poses_) buffers.push_back(b.buffer);
        return buffers;
    }
    VkBuffer ends() const { return ends_.buffer; }
    const std::vector<uint32_t>& line_counts() const { return line_counts_; }  // per object
    uint32_t line_total() const { return line_total_; }
    uint32_t vertex_total() const { return vertex_total_; }

private:
    // [static-buffers]
    // Built once: each mesh's coordinates (shared by all its objects), a
    // table saying where each object's mesh and output vertices are, and the
    // index buffer of every line of every object. Object k's indices point
    // at its own output vertices (first_out + edge end), so one draw covers
    // the whole scene.
    void build_scene_buffers(const nd::Scene& scene) {
        const size_t n = size_t(scene.dim);
        std::vector<float> coords;
        std::vector<uint32_t> mesh_first;
        for (const nd::Mesh& mesh : scene.meshes) {
            mesh_first.push_back(uint32_t(coords.size() / n));
            coords.insert(coords.end(), mesh.coords.begin(), mesh.coords.end());
        }
        std::vector<ObjectInfo> objects;
        std::vector<uint32_t> ends;
        for (const nd::SceneObject& object : scene.objects) {
            const nd::Mesh& mesh = scene.meshes[size_t(object.mesh)];
            const ObjectInfo info{mesh_first[size_t(object.mesh)], uint32_t(mesh.vertex_count()),
                                  vertex_total_, 1.0f / mesh.radius()};
            for (const nd::Edge& e : mesh.edges) {
                ends.push_back(info.first_out + e.a);
                ends.push_back(info.first_out + e.b);
            }
            objects.push_back(info);
            line_counts_.push_back(uint32_t(mesh.edges.size()));
            vertex_total_ += info.vertex_count;
            max_vertices_ = std::max(max_vertices_, info.vertex_count);
        }
        object_count_ = uint32_t(objects.size());
        line_total_ = uint32_t(ends.size() / 2);
        coords_ = vkt::create_device_buffer(gpu_, coords.data(), coords.size() * sizeof(float),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        objects_ =
            vkt::create_device_buffer(gpu_, objects.data(), objects.size() * sizeof(ObjectInfo),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        ends_ = vkt::create_device_buffer(
            gpu_, ends.data(), ends.size() * sizeof(uint32_t),
            VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    }
    // [/static-buffers]

    // [frame-buffers]
    // Per frame in flight, in device-local memory: the poses (the pose pass
    // writes them) and the projected vertices (the draw reads them as a
    // vertex buffer, the rasterisers as storage, --verify copies them out).
    void create_frame_buffers(const vkt::Context& context, const nd::Scene& scene) {
        const VkDeviceSize pose_bytes =
            scene.objects.size() * size_t(scene.dim * scene.dim + scene.dim) * sizeof(float);
        const auto local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        for (uint32_t i = 0; i < context.frames_in_flight; ++i) {
            poses_.push_back(vkt::create_buffer(context.physical, gpu_.device, pose_bytes,
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, local));
            projected_.push_back(vkt::create_buffer(
                context.physical, gpu_.device, vertex_total_ * sizeof(Projected),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                local));
        }
    }
    // [/frame-buffers]

    // [descriptors]
    // Set 0, one per frame in flight: the bindings named above.
    void write_sets(const Layouts& layouts, uint32_t slots) {
        pool_ = storage_pool(gpu_.device, slots, binding_count);
        for (uint32_t i = 0; i < slots; ++i) {
            const VkDescriptorSet set =
                vkt::allocate_descriptor_set(gpu_.device, pool_, layouts.transform);
            VkBuffer buffers[binding_count];
            buffers[coords_binding] = coords_.buffer;
            buffers[objects_binding] = objects_.buffer;
            buffers[poses_binding] = poses_[i].buffer;
            buffers[projected_binding] = projected_[i].buffer;
            for (uint32_t b = 0; b < binding_count; ++b)
                vkt::write_buffer_descriptor(gpu_.device, set, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             buffers[b], 0, VK_WHOLE_SIZE);
            sets_.push_back(set);
        }
    }
    // [/descriptors]

    // [transform-pipeline]
    // n as a specialization constant: the shader's point is float x[N].
    // The workgroup's shape is the tuning's (tuning.hpp): on a GPU one
    // invocation per vertex; on a CPU device fewer invocations, each with
    // its own copy of the matrix (OWN_COPY) and several vertices.
    // --raster binned adds each object's box (transform_boxes.comp).
    void create_pipeline(const vkt::Context& context, int n, VkPipelineLayout layout, bool boxes) {
        struct Constants {
            int32_t n;
            VkBool32 own_copy;
            uint32_t group;
        };
        const Constants constants{n, tuning_.own_matrix_copy, tuning_.transform_group};
        const VkSpecializationMapEntry entries[] = {
            {0, offsetof(Constants, n), sizeof(Constants::n)},
            {1, offsetof(Constants, own_copy), sizeof(Constants::own_copy)},
            {2, offsetof(Constants, group), sizeof(Constants::group)}};
        const VkSpecializationInfo specialization{.mapEntryCount = 3,
                                                  .pMapEntries = entries,
                                                  .dataSize = sizeof(constants),
                                                  .pData = &constants};
        vkt::ShaderModule transform = vkt::load_shader(
            gpu_.device, context.chapter, boxes ? "transform_boxes.comp" : "transform.comp");
        pipeline_ = vkt::create_compute_pipeline(gpu_.device, transform, layout, &specialization);
    }
    // [/transform-pipeline]

    vkt::Gpu gpu_;
    Tuning tuning_;
    uint32_t object_count_ = 0, vertex_total_ = 0, line_total_ = 0, max_vertices_ = 0;
    std::vector<uint32_t> line_counts_;  // [object]
    vkt::Buffer coords_, objects_, ends_;
    std::vector<vkt::Buffer> poses_, projected_;  // [slot]
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;  // [slot]
    vkt::Pipeline pipeline_;
};

}  // namespace ch20
