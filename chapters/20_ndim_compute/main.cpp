// Chapter 20: objects of n dimensions, transformed by a compute pass.
//
// The scenes of chapter 18 (vkt::ndim::make_scene: a tesseract and a 24-cell,
// one n-cube, or 250 of them), drawn another way. Each frame the CPU builds
// one n x n matrix per object (the sines and cosines, once per object); a
// compute pass then transforms and projects every unique vertex of every
// object once, into a storage buffer; and one indexed LINE_LIST draw reads
// that buffer as its vertex buffer and draws every line of every object.
// With --raster compute, a second compute pass draws the lines itself into a
// storage buffer of one word per pixel (one invocation per line, atomicMax
// per pixel), laid out as the colour target's pixels, and a copy, or on a
// GPU a compute pass, moves it onto the colour target (compute_raster.hpp,
// resolve_pass.hpp). With --raster binned, the
// lines are sorted into screen tiles first and each workgroup draws one tile
// in shared memory (binned_raster.hpp): the same picture, pixel for pixel.

#include "binned_raster.hpp"
#include "compute_raster.hpp"
#include "scene_state.hpp"
#include "tuning.hpp"
#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/domains/ndim.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/frame/stats.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/ndim_controls.hpp"
#include "vkt/scene/ndim_options.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

namespace nd = vkt::ndim;

using ch20::ObjectInfo, ch20::Projected, ch20::Push;

class NdimCompute : public vkt::Renderer {
public:
    explicit NdimCompute(const vkt::Context& context)
        : gpu_(context.gpu()), device_(context.device) {
        tuning_ = ch20::Tuning::for_device(context.properties);
        const auto& options = context.options;
        const nd::SceneChoice choice = nd::scene_choice(options);
        const std::string& scene = choice.scene;
        n_ = choice.n;
        still_ = choice.still;
        verify_ = options.has("--verify");
        verify_raster_ = verify_ && options.text("--verify") == "raster";
        verify_frame_ = options.frames.value_or(1) - 1;
        benchmark_ = options.benchmark;
        scene_ = nd::make_scene(scene, n_, still_);
        keys_ = nd::Controls(
            n_, choice.orthographic ? nd::Projection::orthographic : nd::Projection::perspective);

        // [static-buffers]
        // Built once: each mesh's coordinates (shared by all its objects),
        // a table saying where each object's mesh and output vertices are,
        // and the index buffer of every line of every object. Object k's
        // indices point at its own output vertices (first_out + edge end), so
        // one draw covers the whole scene.
        std::vector<float> coords;
        std::vector<uint32_t> mesh_first;
        for (const nd::Mesh& mesh : scene_.meshes) {
            mesh_first.push_back(uint32_t(coords.size() / size_t(n_)));
            coords.insert(coords.end(), mesh.coords.begin(), mesh.coords.end());
        }
        std::vector<ObjectInfo> objects;
        std::vector<uint32_t> ends, line_counts;
        for (const nd::SceneObject& object : scene_.objects) {
            const nd::Mesh& mesh = scene_.meshes[size_t(object.mesh)];
            const ObjectInfo info{mesh_first[size_t(object.mesh)], uint32_t(mesh.vertex_count()),
                                  vertex_total_, 1.0f / mesh.radius()};
            for (const nd::Edge& e : mesh.edges) {
                ends.push_back(info.first_out + e.a);
                ends.push_back(info.first_out + e.b);
            }
            objects.push_back(info);
            line_counts.push_back(uint32_t(mesh.edges.size()));
            vertex_total_ += info.vertex_count;
            max_vertices_ = std::max(max_vertices_, info.vertex_count);
        }
        line_total_ = uint32_t(ends.size() / 2);
        coords_ = vkt::create_device_buffer(gpu_, coords.data(), coords.size() * sizeof(float),
                                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        objects_ =
            vkt::create_device_buffer(gpu_, objects.data(), objects.size() * sizeof(ObjectInfo),
                                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        ends_ = vkt::create_device_buffer(
            gpu_, ends.data(), ends.size() * sizeof(uint32_t),
            VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        // [/static-buffers]

        // [frame-buffers]
        // Per frame in flight: the poses the CPU writes (host-visible), and
        // the projected vertices the transform pass writes (device-local: the
        // draw reads them as a vertex buffer, the rasteriser as storage).
        pose_floats_ = size_t(n_) * size_t(n_) + size_t(n_);
        const VkDeviceSize pose_bytes = scene_.objects.size() * pose_floats_ * sizeof(float);
        for (uint32_t i = 0; i < context.frames_in_flight; ++i) {
            poses_.push_back(
                vkt::create_host_buffer(gpu_, pose_bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            projected_.push_back(vkt::create_buffer(
                context.physical, device_, vertex_total_ * sizeof(Projected),
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT));
        }
        // [/frame-buffers]
        std::fprintf(stderr,
                     "20_ndim_compute: %s scene, n = %d, %zu objects, %u vertices, %u lines per "
                     "frame, raster %s, eye at %.3g\n",
                     scene.c_str(), n_, scene_.objects.size(), vertex_total_, line_total_,
                     options.text("--raster").c_str(), scene_.eye);
        std::fprintf(stderr, "20_ndim_compute: %s\n", tuning_.describe().c_str());

        // [descriptors]
        // One set layout for all the passes: 0 coordinates, 1 object table,
        // 2 poses, 3 projected vertices, 4 line ends, 5 and 6 the compute
        // rasterisers' pixels and palette, 7 to 9 the binned one's own.
        constexpr uint32_t binding_count = 10;
        VkDescriptorSetLayoutBinding bindings[binding_count];
        for (uint32_t b = 0; b < binding_count; ++b)
            bindings[b] = {.binding = b,
                           .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                           .descriptorCount = 1,
                           .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT};
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, binding_count * context.frames_in_flight}};
        pool_ = vkt::create_descriptor_pool(device_, context.frames_in_flight, sizes);
        for (uint32_t i = 0; i < context.frames_in_flight; ++i) {
            const VkDescriptorSet set = vkt::allocate_descriptor_set(device_, pool_, set_layout_);
            const VkBuffer buffers[] = {coords_.buffer, objects_.buffer, poses_[i].buffer,
                                        projected_[i].buffer, ends_.buffer};
            for (uint32_t b = 0; b < 5; ++b)
                vkt::write_buffer_descriptor(device_, set, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                             buffers[b], 0, VK_WHOLE_SIZE);
            sets_.push_back(set);
        }
        const VkPushConstantRange push_range{
            .stageFlags = push_stages, .offset = 0, .size = sizeof(Push)};
        const VkDescriptorSetLayout set_layout = set_layout_;
        layout_ = vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&push_range, 1});
        // [/descriptors]

        // [transform-pipeline]
        // n as a specialization constant: the shader's point is float x[N].
        // The workgroup's shape is the tuning's (tuning.hpp): on a GPU one
        // invocation per vertex; on a CPU device fewer invocations, each with
        // its own copy of the matrix (OWN_COPY) and several vertices.
        // --raster binned adds each object's box (transform_boxes.comp).
        const bool binned = options.text("--raster") == "binned";
        if (binned) ch20::BinnedRaster::check_device(context);
        struct Constants {
            int32_t n;
            VkBool32 own_copy;
            uint32_t group;
        };
        const Constants constants{n_, tuning_.own_matrix_copy, tuning_.transform_group};
        const VkSpecializationMapEntry entries[] = {
            {0, offsetof(Constants, n), sizeof(Constants::n)},
            {1, offsetof(Constants, own_copy), sizeof(Constants::own_copy)},
            {2, offsetof(Constants, group), sizeof(Constants::group)}};
        const VkSpecializationInfo specialization{.mapEntryCount = 3,
                                                  .pMapEntries = entries,
                                                  .dataSize = sizeof(constants),
                                                  .pData = &constants};
        vkt::ShaderModule transform = vkt::load_shader(
            device_, context.chapter, binned ? "transform_boxes.comp" : "transform.comp");
        transform_ = vkt::create_compute_pipeline(device_, transform, layout_, &specialization);
        // [/transform-pipeline]

        // [line-pipeline]
        // The projected vertices, 16 bytes each, straight from the storage
        // buffer the transform pass wrote.
        const VkVertexInputBindingDescription binding{
            .binding = 0, .stride = sizeof(Projected), .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {.location = 0, .binding = 0, .format = VK_FORMAT_R32G32_SFLOAT, .offset = 0},
            {.location = 1,
             .binding = 0,
             .format = VK_FORMAT_R8G8B8A8_UNORM,
             .offset = offsetof(Projected, colour)},
        };
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "lines.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "lines.frag");
        lines_ =
            vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                    .fragment = fragment,
                                                    .layout = layout_,
                                                    .bindings = {&binding, 1},
                                                    .attributes = attributes,
                                                    .topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
                                                    .color_formats = {context.color_format}});
        // [/line-pipeline]
        // --raster compute: the lines drawn by a compute pass instead
        // (compute_raster.hpp), through the same sets and pipeline layout;
        // --raster binned: the same, tile by tile (binned_raster.hpp).
        if (options.text("--raster") != "graphics")
            raster_.emplace(context, tuning_, layout_, sets_, line_total_);
        if (binned) binned_.emplace(context, tuning_, layout_, sets_, line_counts);
    }

    // The compute rasterisers' buffers follow the window's size.
    void resize(VkExtent2D extent) override {
        if (raster_) raster_->resize(extent, sets_);
        if (binned_) binned_->resize(extent, sets_);
    }

    // With --benchmark, the CPU's share: building the poses each frame.
    ~NdimCompute() override {
        if (benchmark_)
            std::fprintf(stderr, "20_ndim_compute: CPU poses per frame, ms: %s\n",
                         vkt::json_summary(cpu_ms_).c_str());
    }

    void record(const vkt::Frame& frame) override {
        const float dt = float(frame.time - last_time_);
        last_time_ = frame.time;
        keys_.steer(frame.input, dt);
        if (!still_ && !keys_.paused) spin_time_ += dt;
        const auto cpu_start = std::chrono::steady_clock::now();
        write_poses(frame.slot);
        if (benchmark_)
            cpu_ms_.push_back(std::chrono::duration<double, std::milli>(
                                  std::chrono::steady_clock::now() - cpu_start)
                                  .count());

        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const Push push{
            {1.0f / (scene_.view_half_height * aspect), -1.0f / scene_.view_half_height},
            scene_.eye,
            keys_.projection == nd::Projection::orthographic ? 1u : 0u,
            uint32_t(scene_.objects.size()),
            line_total_,
            {frame.extent.width, frame.extent.height}};
        if (verify_ && frame.index == verify_frame_) verify(frame, push);

        const VkCommandBuffer cmd = frame.cmd;
        const VkBuffer projected = projected_[frame.slot].buffer;
        if (binned_) binned_->clear_boxes(cmd);
        {
            auto scope = frame.gpu_scope("transform");
            record_transform(cmd, frame.slot, push);
        }
        if (binned_) {
            {
                auto scope = frame.gpu_scope("bin");
                binned_->bin(cmd);
            }
            auto scope = frame.gpu_scope("raster");
            binned_->draw(cmd, *raster_, frame.timer, frame.slot);
            auto finish = frame.gpu_scope(raster_->resolves(frame) ? "resolve" : "copy");
            raster_->finish(frame);
            return;
        }
        if (raster_) {
            auto scope = frame.gpu_scope("raster");
            raster_->draw(cmd, projected);
            auto finish = frame.gpu_scope(raster_->resolves(frame) ? "resolve" : "copy");
            raster_->finish(frame);
            return;
        }
        // [draw]
        // The transform pass's writes, made visible to the vertex input; then
        // one indexed draw for every line of every object.
        vkt::buffer_barrier(cmd, projected, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                            VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
        auto scope = frame.gpu_scope("raster");
        begin_rendering(frame);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lines_);
        vkt::set_viewport_and_scissor(cmd, frame.extent);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &projected, &offset);
        vkCmdBindIndexBuffer(cmd, ends_.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, 2 * line_total_, 1, 0, 0, 0);
        vkCmdEndRendering(cmd);
        // [/draw]
    }

private:
    static constexpr VkShaderStageFlags push_stages =
        VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

    // [poses]
    // Once per object per frame on the CPU: the angles at this time, the
    // rotation built row by row (O(n^3): vkt::ndim::rotation_matrix_by_rows),
    // the scale folded into its columns. The shader gets M and p and needs
    // no sine or cosine at all.
    void write_poses(uint32_t slot) {
        auto* out = static_cast<float*>(poses_[slot].mapped);
        for (const nd::SceneObject& object : scene_.objects) {
            const nd::Transform t = keys_.pose(object, spin_time_);
            const nd::Matrix r = nd::rotation_matrix_by_rows(n_, t.angles);
            for (int row = 0; row < n_; ++row)
                for (int col = 0; col < n_; ++col) *out++ = r(row, col) * t.scale[size_t(col)];
            for (int k = 0; k < n_; ++k) *out++ = t.position[size_t(k)];
        }
    }
    // [/poses]

    // [dispatch]
    // x runs over the largest mesh's vertices in workgroups of 128 (64 on a
    // CPU device, each invocation taking Tuning::vertices_per_lane), y the objects.
    void record_transform(VkCommandBuffer cmd, uint32_t slot, const Push& push) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, transform_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[slot], 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout_, push_stages, 0, sizeof(Push), &push);
        const uint32_t per_group = tuning_.transform_group * tuning_.vertices_per_lane;
        vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(max_vertices_, per_group)),
                      uint32_t(scene_.objects.size()), 1);
    }
    // [/dispatch]

    void begin_rendering(const vkt::Frame& frame) {
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.006f, 0.006f, 0.012f, 1.0f}});
    }

    // [verify]
    // --verify cpu: run the transform pass alone on the last frame's poses,
    // read the projected vertices back and compare each with the CPU
    // reference (scene_state.hpp: vkt::ndim's per-plane transform_point and
    // project_to_2d, a different path from the matrix the GPU uses). Throws
    // above the tolerance. (--verify raster: binned_raster.hpp.)
    void verify(const vkt::Frame& frame, const Push& push) {
        const uint32_t slot = frame.slot;
        if (verify_raster_)
            return binned_->verify(*raster_, frame.extent, projected_[slot].buffer,
                                   [&](VkCommandBuffer cmd) { record_transform(cmd, slot, push); });
        const VkDeviceSize bytes = vertex_total_ * sizeof(Projected);
        vkt::Buffer host = vkt::create_host_buffer(gpu_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            record_transform(cmd, slot, push);
            vkt::buffer_barrier(cmd, projected_[slot].buffer,
                                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy region{0, 0, bytes};
            vkCmdCopyBuffer(cmd, projected_[slot].buffer, host.buffer, 1, &region);
            vkt::buffer_barrier(cmd, host.buffer, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                                VK_ACCESS_2_HOST_READ_BIT);
        });
        const ch20::Comparison c = ch20::compare_with_cpu(
            scene_, keys_, spin_time_, push, static_cast<const Projected*>(host.mapped));
        constexpr double tolerance = 1e-4;  // clip units: 0.1 pixel across 1920
        std::fprintf(stderr,
                     "20_ndim_compute: verify: %zu vertices (%zu behind the eye), largest "
                     "difference from the CPU: position %.3g (clip units), depth %.3g; "
                     "tolerance %g, %zu visibility mismatches\n",
                     c.vertices, c.hidden, c.position, c.depth, tolerance, c.mismatched);
        if (!(c.position <= tolerance && c.depth <= tolerance) || c.mismatched != 0)
            throw vkt::Error("verify: the GPU's projected vertices differ from the CPU's");
    }
    // [/verify]

    vkt::Gpu gpu_;
    VkDevice device_;
    int n_ = 4;
    bool still_ = false, verify_ = false, verify_raster_ = false, benchmark_ = false;
    std::vector<double> cpu_ms_;
    uint64_t verify_frame_ = 0;
    nd::Scene scene_;
    nd::Controls keys_{4, nd::Projection::perspective};  // chapter 18's keys
    double last_time_ = 0.0;
    float spin_time_ = 0.0f;
    uint32_t vertex_total_ = 0, line_total_ = 0, max_vertices_ = 0;
    ch20::Tuning tuning_;  // the passes' shapes for this device (tuning.hpp)
    size_t pose_floats_ = 0;
    vkt::Buffer coords_, objects_, ends_;
    std::vector<vkt::Buffer> poses_, projected_;  // [slot]
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;  // [slot]
    vkt::PipelineLayout layout_;
    vkt::Pipeline transform_, lines_;
    std::optional<ch20::ComputeRaster> raster_;  // --raster compute or binned
    std::optional<ch20::BinnedRaster> binned_;   // --raster binned
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{
        .name = "20_ndim_compute", .title = "20 - ndim_compute", .input = vkt::InputUse::keys};
    // The build's SPIR-V gives compute shaders their workgroup size as
    // LocalSizeId, which needs maintenance4 (as in chapter 13).
    spec.requirements.features = {VKT_FEATURE_13(maintenance4)};
    // The compute rasterisers store their pixels into the colour target
    // where they can (resolve_pass.hpp): a storage view of it, written
    // without a format qualifier.
    spec.storage_target = true;
    spec.transfers_into_target = true;  // where they cannot, they copy their pixels in
    spec.requirements.optional_features = {VKT_FEATURE_10(shaderStorageImageWriteWithoutFormat)};
    // --scene, --dim, --projection and --motion: vkt/scene/ndim_options.hpp.
    spec.options = vkt::ndim::scene_options();
    spec.check_options = [](const vkt::Options& options) {
        vkt::ndim::scene_choice(options);
        if (options.has("--verify") && options.text("--verify") == "raster" &&
            options.text("--raster") != "binned")
            throw vkt::UsageError(
                "--verify raster compares --raster binned with --raster compute: "
                "use it with --raster binned");
    };
    spec.options.insert(
        spec.options.end(),
        {
            {.name = "--raster",
             .type = vkt::OptionType::choice,
             .help = "draw the lines with the graphics pipeline, a compute pass, or a compute "
                     "pass tile by tile",
             .default_value = "graphics",
             .choices = {"graphics", "compute", "binned"}},
            {.name = "--to-target",
             .type = vkt::OptionType::choice,
             .help = "how the compute rasterisers' pixels reach the colour target: a compute "
                     "pass that stores them, a fill and a copy, or auto (store on a GPU)",
             .default_value = "auto",
             .choices = {"auto", "store", "copy"}},
            {.name = "--verify",
             .type = vkt::OptionType::choice,
             .help = "on the last frame, check the GPU's projected vertices against the CPU's "
                     "(cpu), or the binned rasteriser's pixels against the compute one's (raster)",
             .choices = {"cpu", "raster"}},
        });
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<NdimCompute>(context);
    });
}
