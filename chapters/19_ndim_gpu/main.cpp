// Chapter 19: objects of n dimensions, on the GPU.
//
// The same scenes as chapter 18 (vkt::ndim::make_scene: a tesseract and a
// 24-cell, one n-cube, or 250 of them), but the CPU no longer touches a
// vertex. The meshes go to the GPU once, into a storage buffer of n floats
// per vertex and an index buffer of edge pairs; each frame the CPU writes only
// each object's raw transform, n(n+3)/2 floats, into a second storage buffer.
// The vertex shader pulls its vertex by gl_VertexIndex, scales it, turns it in
// every plane and projects it, O(n^2) per vertex and no matrix anywhere. The
// dimension n is a specialization constant: one SPIR-V file for every n.
// --verify cpu captures the projected vertices in a storage buffer and checks
// them against the CPU (verify.hpp).

#include "invocation_counter.hpp"
#include "verify.hpp"
#include "vkt/core/check.hpp"
#include "vkt/domains/ndim.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/frame/stats.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/ndim_controls.hpp"
#include "vkt/scene/ndim_options.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

namespace nd = vkt::ndim;

// [push]
// The push constants, laid out as ndim.glsl's Push block (std430-like
// offsets: every member 4 bytes, the vec2 first). Pushed whole before each
// draw; what changes from draw to draw are integers: which object (which
// transform), and the mesh's radius for the colour.
struct Push {
    float to_clip[2];
    float eye;
    int32_t orthographic;
    int32_t vertex_count;
    float inverse_radius;
    int32_t object;
};
static_assert(sizeof(Push) == 28);
// [/push]

// The largest error --verify accepts, relative to the coordinate or, on the
// screen, to the half screen (1 in clip units): 1e-4 is a twentieth of a
// pixel at 1080 rows.
constexpr double verify_tolerance = 1e-4;

class NdimGpu : public vkt::Renderer {
public:
    explicit NdimGpu(const vkt::Context& context) : gpu_(context.gpu()), device_(context.device) {
        const auto& options = context.options;
        const nd::SceneChoice choice = nd::scene_choice(options);
        const std::string& scene = choice.scene;
        n_ = choice.n;
        controls_ = nd::Controls(
            n_, choice.orthographic ? nd::Projection::orthographic : nd::Projection::perspective,
            "19_ndim_gpu");
        still_ = choice.still;
        verify_ = options.has("--verify");
        if (verify_ && !context.features.has(VKT_FEATURE_10(vertexPipelineStoresAndAtomics)))
            throw vkt::Error(
                "--verify writes from the vertex shader, which needs the "
                "vertexPipelineStoresAndAtomics feature; this device does not have it");
        benchmark_ = options.benchmark;
        scene_ = nd::make_scene(scene, n_, still_);
        // --eye moves the eye nearer than the scene's safe distance, so that
        // vertices reach it and are clipped (the tests use it).
        if (options.has("--eye")) scene_.eye = float(options.number("--eye"));

        // [meshes]
        // Every mesh once, for the whole run: all vertices in one storage
        // buffer (n floats each), all edges in one index buffer (two vertex
        // numbers each, counted from the mesh's first vertex). A draw finds
        // its mesh by firstIndex and vertexOffset.
        const bool by_vertex = options.text("--edge-order") == "vertex";
        std::vector<float> coords;
        std::vector<uint32_t> indices;
        for (const nd::Mesh& mesh : scene_.meshes) {
            meshes_.push_back({.first_vertex = int32_t(coords.size() / size_t(n_)),
                               .first_index = uint32_t(indices.size()),
                               .index_count = uint32_t(mesh.edges.size() * 2),
                               .vertex_count = uint32_t(mesh.vertex_count()),
                               .inverse_radius = 1.0f / mesh.radius()});
            coords.insert(coords.end(), mesh.coords.begin(), mesh.coords.end());
            // By vertex: the edges from vertex 0 first, then those from 1, ...
            // so that a vertex's edges lie close together and the GPU can
            // reuse its shaded result instead of shading it once per edge.
            std::vector<nd::Edge> edges = mesh.edges;  // by axis, as make_cube lists them
            if (by_vertex)
                std::stable_sort(edges.begin(), edges.end(),
                                 [](const nd::Edge& x, const nd::Edge& y) { return x.a < y.a; });
            for (const nd::Edge& edge : edges) indices.insert(indices.end(), {edge.a, edge.b});
        }
        vertex_count_ = uint32_t(coords.size() / size_t(n_));
        vertices_ = vkt::create_device_buffer(gpu_, coords.data(), coords.size() * sizeof(float),
                                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        indices_ =
            vkt::create_device_buffer(gpu_, indices.data(), indices.size() * sizeof(uint32_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        // [/meshes]

        // [transform-buffers]
        // The raw transforms, rewritten every frame: n(n+3)/2 floats per
        // object, one host-visible buffer per frame in flight (250 12-cubes:
        // 250 x 90 x 4 = 90 KB, where chapter 18 wrote 141 MiB of lines).
        floats_per_object_ = size_t(n_) * size_t(n_ + 3) / 2;
        const VkDeviceSize transform_bytes =
            scene_.objects.size() * floats_per_object_ * sizeof(float);
        for (uint32_t i = 0; i < context.frames_in_flight; ++i)
            transforms_.push_back(
                vkt::create_host_buffer(gpu_, transform_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
        // [/transform-buffers]
        if (verify_)  // one vec4 per vertex of the pool per object: see capture.vert
            capture_ = vkt::create_host_buffer(
                gpu_, VkDeviceSize(scene_.objects.size()) * vertex_count_ * 4 * sizeof(float),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::fprintf(
            stderr,
            "19_ndim_gpu: %s scene, n = %d, %zu objects, %zu lines per frame, eye at %.3g; "
            "%u vertices and %zu indices on the GPU, %llu bytes of transforms per frame\n",
            scene.c_str(), n_, scene_.objects.size(), scene_.line_count(), scene_.eye,
            vertex_count_, indices.size(), static_cast<unsigned long long>(transform_bytes));

        // [descriptors]
        // Set 0: binding 0 the vertices, 1 this frame's transforms, 2 the
        // capture buffer (--verify only; the drawing shader never reads it, so
        // it may stay unwritten). One set per frame in flight.
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
            {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             3 * context.frames_in_flight};
        pool_ = vkt::create_descriptor_pool(device_, context.frames_in_flight, {&pool_size, 1});
        for (uint32_t i = 0; i < context.frames_in_flight; ++i) {
            const VkDescriptorSet set = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
            vkt::write_buffer_descriptor(device_, set, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                         vertices_.buffer, 0, VK_WHOLE_SIZE);
            vkt::write_buffer_descriptor(device_, set, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                         transforms_[i].buffer, 0, VK_WHOLE_SIZE);
            if (verify_)
                vkt::write_buffer_descriptor(device_, set, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             capture_.buffer, 0, VK_WHOLE_SIZE);
            sets_.push_back(set);
        }
        const VkPushConstantRange push_range{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push)};
        const VkDescriptorSetLayout set_layout = set_layout_;
        layout_ = vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&push_range, 1});
        // [/descriptors]

        // [specialization]
        // n becomes constant_id 0 of the vertex shader: 4 bytes at offset 0
        // of `data`. The driver compiles the pipeline with N = n, as if the
        // shader had been written for that n alone.
        const int32_t dimension = n_;
        const VkSpecializationMapEntry entry{.constantID = 0, .offset = 0, .size = sizeof(int32_t)};
        const VkSpecializationInfo specialization{
            .mapEntryCount = 1,
            .pMapEntries = &entry,
            .dataSize = sizeof(dimension),
            .pData = &dimension,
        };
        // [/specialization]

        // [pipeline]
        // No vertex bindings, no attributes: the shader pulls what it needs.
        // LINE_LIST: indices 2k and 2k+1 make line k.
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "lines.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "lines.frag");
        pipeline_ =
            vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                    .fragment = fragment,
                                                    .layout = layout_,
                                                    .topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
                                                    .color_formats = {context.color_format},
                                                    .vertex_specialization = &specialization});
        // [/pipeline]
        // --benchmark: how many times the vertex shader ran per frame
        // (invocation_counter.hpp), which shows how many shaded vertices the
        // post-transform cache reused.
        if (benchmark_ && context.features.has(VKT_FEATURE_10(pipelineStatisticsQuery)))
            invocations_ = ch19::InvocationCounter(device_, context.frames_in_flight);
        if (verify_) {
            // The capture pass draws nothing: no fragment shader, no target.
            vkt::ShaderModule capture = vkt::load_shader(device_, context.chapter, "capture.vert");
            capture_pipeline_ =
                vkt::create_graphics_pipeline(device_, {.vertex = capture,
                                                        .layout = layout_,
                                                        .topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
                                                        .vertex_specialization = &specialization});
        }
    }

    // With --benchmark: the CPU's share of a frame, writing the transforms
    // and recording the draws.
    ~NdimGpu() override {
        if (benchmark_)
            std::fprintf(stderr, "19_ndim_gpu: CPU transforms and draws per frame, ms: %s\n",
                         vkt::json_summary(cpu_ms_).c_str());
        const std::vector<double> invocations = invocations_.finish();
        if (invocations.empty()) return;
        uint64_t indices = 0, vertices = 0;
        for (const nd::SceneObject& object : scene_.objects) {
            indices += meshes_[size_t(object.mesh)].index_count;
            vertices += meshes_[size_t(object.mesh)].vertex_count;
        }
        std::fprintf(stderr,
                     "19_ndim_gpu: vertex shader invocations per frame: %s, for %llu indices "
                     "and %llu vertices\n",
                     vkt::json_summary(invocations).c_str(),
                     static_cast<unsigned long long>(indices),
                     static_cast<unsigned long long>(vertices));
    }

    void record(const vkt::Frame& frame) override {
        const float dt = float(frame.time - last_time_);
        last_time_ = frame.time;
        controls_.steer(frame.input, dt);
        if (!still_ && !controls_.paused) spin_time_ += dt;
        const auto cpu_start = std::chrono::steady_clock::now();

        // [write-transforms]
        // This frame's pose of each object, packed as the shader reads it:
        // position, scale, angles. Coherent memory: the submit makes it visible.
        auto* out = static_cast<float*>(transforms_[frame.slot].mapped);
        for (size_t o = 0; o < scene_.objects.size(); ++o) {
            const std::vector<float> packed =
                controls_.pose(scene_.objects[o], spin_time_).packed();
            std::memcpy(out + o * floats_per_object_, packed.data(), packed.size() * sizeof(float));
        }
        // [/write-transforms]
        last_ = {frame.slot, frame.extent};  // what verify() checks
        invocations_.start_frame(frame.cmd, frame.slot);

        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.006f, 0.006f, 0.012f, 1.0f}});
        {
            // The transform happens inside the draws, in the vertex shader:
            // one scope times transform and rasterisation together.
            auto scope = frame.gpu_scope("raster");
            invocations_.begin(frame.cmd, frame.slot);
            draw_objects(frame.cmd, frame.slot, frame.extent, pipeline_);
            invocations_.end(frame.cmd, frame.slot);
        }
        vkCmdEndRendering(frame.cmd);
        if (benchmark_)
            cpu_ms_.push_back(std::chrono::duration<double, std::milli>(
                                  std::chrono::steady_clock::now() - cpu_start)
                                  .count());
    }

private:
    struct MeshRange {
        int32_t first_vertex;  // in the vertex buffer: the draw's vertexOffset
        uint32_t first_index, index_count;
        uint32_t vertex_count;
        float inverse_radius;
    };

    Push frame_push(VkExtent2D extent) const {
        const float aspect = float(extent.width) / float(extent.height);
        return {
            .to_clip = {1.0f / (scene_.view_half_height * aspect), -1.0f / scene_.view_half_height},
            .eye = scene_.eye,
            .orthographic = controls_.projection == nd::Projection::orthographic ? 1 : 0,
            .vertex_count = int32_t(vertex_count_),
            .inverse_radius = 1.0f,
            .object = 0};
    }

    // [draw]
    // One indexed draw per object: its mesh's edges, its transform chosen by
    // the object index in the push constants. gl_VertexIndex is the index
    // from the buffer plus vertexOffset: the vertex's place in the pool.
    void draw_objects(VkCommandBuffer cmd, uint32_t slot, VkExtent2D extent,
                      VkPipeline pipeline) const {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        vkt::set_viewport_and_scissor(cmd, extent);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &sets_[slot],
                                0, nullptr);
        vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        Push push = frame_push(extent);
        for (size_t o = 0; o < scene_.objects.size(); ++o) {
            const MeshRange& mesh = meshes_[size_t(scene_.objects[o].mesh)];
            push.object = int32_t(o);
            push.inverse_radius = mesh.inverse_radius;
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push), &push);
            vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, mesh.first_vertex, 0);
        }
    }
    // [/draw]

    // [verify]
    // --verify cpu, once the runner's loop is over (the GPU idle): the last
    // frame's draws again with the capture pipeline, in a pass with no
    // attachments, on their own submit; then every vertex of every object
    // the GPU wrote is compared with the CPU's transform and projection, both
    // the per-plane path and chapter 18's matrix (verify.hpp).
    void verify() override {
        if (!verify_) return;
        const Last& frame = last_;
        std::memset(capture_.mapped, 0, size_t(capture_.size));
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            const VkRenderingInfo nothing{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                          .renderArea = {{0, 0}, frame.extent},
                                          .layerCount = 1};
            vkCmdBeginRendering(cmd, &nothing);
            draw_objects(cmd, frame.slot, frame.extent, capture_pipeline_);
            vkCmdEndRendering(cmd);
            vkt::buffer_barrier(cmd, capture_.buffer, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                VK_ACCESS_2_HOST_READ_BIT);
        });
        const ch19::Comparison c =
            ch19::compare_with_cpu(scene_, controls_, spin_time_, frame_push(frame.extent).to_clip,
                                   static_cast<const float*>(capture_.mapped));
        std::fprintf(stderr,
                     "19_ndim_gpu: verify cpu: %zu vertices of %zu objects, GPU vs CPU max error "
                     "%.3g (per-plane path), %.3g (chapter 18's matrix), relative, "
                     "tolerance %.0e; %zu clipped, %zu visibility mismatches, %zu not written\n",
                     c.checked, scene_.objects.size(), c.plane_error, c.matrix_error,
                     verify_tolerance, c.clipped, c.mismatched, c.missing);
        if (c.missing > 0 || c.mismatched > 0 || !(c.plane_error <= verify_tolerance) ||
            !(c.matrix_error <= verify_tolerance))
            throw vkt::Error("verify cpu: the GPU's vertices differ from the CPU's");
    }
    // [/verify]

    vkt::Gpu gpu_;
    VkDevice device_;
    int n_ = 4;
    nd::Controls controls_{4, nd::Projection::perspective};  // chapter 18's keys
    bool still_ = false, benchmark_ = false, verify_ = false;
    struct Last {
        uint32_t slot = 0;
        VkExtent2D extent{};
    } last_;  // the last frame recorded
    std::vector<double> cpu_ms_;
    nd::Scene scene_;
    std::vector<MeshRange> meshes_;
    uint32_t vertex_count_ = 0;
    size_t floats_per_object_ = 0;
    double last_time_ = 0.0;
    float spin_time_ = 0.0f;
    vkt::Buffer vertices_, indices_, capture_;
    std::vector<vkt::Buffer> transforms_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_, capture_pipeline_;
    ch19::InvocationCounter invocations_;  // --benchmark, where the device can
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{
        .name = "19_ndim_gpu", .title = "19 - ndim_gpu", .input = vkt::InputUse::keys};
    // A clipped vertex cuts its lines away with a clip distance; --verify
    // writes from the vertex shader when the device allows it; --benchmark
    // counts vertex shader invocations where the device can.
    spec.requirements.features = {VKT_FEATURE_10(shaderClipDistance)};
    spec.requirements.optional_features = {VKT_FEATURE_10(vertexPipelineStoresAndAtomics),
                                           VKT_FEATURE_10(pipelineStatisticsQuery)};
    // --scene, --dim, --projection and --motion: vkt/scene/ndim_options.hpp.
    spec.options = vkt::ndim::scene_options();
    spec.check_options = [](const vkt::Options& options) { vkt::ndim::scene_choice(options); };
    spec.options.insert(
        spec.options.end(),
        {
            {.name = "--edge-order",
             .type = vkt::OptionType::choice,
             .help = "the index buffer's edges by vertex (reused shading) or by axis (chapter 18's "
                     "order)",
             .default_value = "vertex",
             .choices = {"vertex", "axis"}},
            {.name = "--eye",
             .type = vkt::OptionType::number,
             .value_name = "D",
             .help = "the eye distance on each last axis (default: the scene's, far enough for no "
                     "clipping)",
             .min = 0.1,
             .max = 1000},
            {.name = "--verify",
             .type = vkt::OptionType::choice,
             .value_name = "CHECK",
             .help = "cpu: capture the last frame's projected vertices, compare with the CPU",
             .choices = {"cpu"}},
        });
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<NdimGpu>(context);
    });
}
