// Chapter 20: objects of n dimensions, transformed by a compute pass.
//
// The scenes of chapter 18 (vkt::ndim::make_scene: a tesseract and a 24-cell,
// one n-cube, or 250 of them), drawn another way. Each frame a compute pass
// builds one n x n matrix per object (pose_pass.hpp: the sines and cosines,
// once per object, from angles uploaded once); a second transforms and
// projects every unique vertex of every object once, into a storage buffer
// (transform_pass.hpp); and one indexed LINE_LIST draw reads that buffer as
// its vertex buffer and draws every line of every object. The CPU records.
// With --raster compute, a second compute pass draws the lines itself into a
// storage buffer of one word per pixel (one invocation per line, atomicMax
// per pixel), laid out as the colour target's pixels, and a copy, or on a
// GPU a compute pass, moves it onto the colour target (compute_raster.hpp,
// resolve_pass.hpp). With --raster binned, the
// lines are sorted into screen tiles first and each workgroup draws one tile
// in shared memory (binned_raster.hpp): the same picture, pixel for pixel.

#include "binned_raster.hpp"
#include "compute_raster.hpp"
#include "layouts.hpp"
#include "pose_pass.hpp"
#include "scene_state.hpp"
#include "transform_pass.hpp"
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

using ch20::Projected, ch20::Push;

class NdimCompute : public vkt::Renderer {
public:
    // [constructor]
    // The steps in the order the passes need each other: the options and the
    // scene; the layout every compute pass shares; the transform pass, which
    // owns the scene's buffers, and the pose pass, which writes its poses;
    // the line pipeline; the compute rasterisers, if asked for.
    explicit NdimCompute(const vkt::Context& context)
        : gpu_(context.gpu()), device_(context.device) {
        read_options(context);
        create_layouts();
        transform_.emplace(context, scene_, tuning_, layouts_, binned_raster_);
        poses_.emplace(context, scene_, transform_->poses());
        describe();
        create_line_pipeline(context);
        create_rasterisers(context);
    }
    // [/constructor]

    // The compute rasterisers' buffers follow the window's size.
    void resize(VkExtent2D extent) override {
        if (raster_) raster_->resize(extent);
        if (binned_) binned_->resize(extent);
    }

    void record(const vkt::Frame& frame) override {
        const float dt = float(frame.time - last_time_);
        last_time_ = frame.time;
        keys_.steer(frame.input, dt);
        if (!still_ && !keys_.paused) spin_time_ += dt;
        const Push push = make_push(frame.extent);
        last_ = {frame.slot, frame.extent, push};  // what verify() checks

        const VkCommandBuffer cmd = frame.cmd;
        const VkBuffer projected = transform_->projected(frame.slot);
        {
            auto scope = frame.gpu_scope("pose");  // every object's matrix, on the GPU
            poses_->record(cmd, frame.slot, spin_time_, keys_);
        }
        if (binned_) binned_->clear_boxes(cmd);
        {
            auto scope = frame.gpu_scope("transform");
            transform_->record(cmd, layouts_.pipeline, frame.slot, push);
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
        // The target comes untouched (ChapterSpec::target_layout): into the
        // layout for drawing, once the runner says it may be written.
        vkt::image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, frame.target_ready,
                           VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        vkt::begin_rendering(cmd, frame.target_view, frame.extent,
                             {{0.006f, 0.006f, 0.012f, 1.0f}});
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lines_);
        vkt::set_viewport_and_scissor(cmd, frame.extent);
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &projected, &offset);
        vkCmdBindIndexBuffer(cmd, transform_->ends(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, 2 * transform_->line_total(), 1, 0, 0, 0);
        vkCmdEndRendering(cmd);
        // [/draw]
    }

    // [layout-after]
    // Each path says how its last write left the target: the resolve's compute
    // storage in GENERAL, the copy's TRANSFER_DST, the lines' colour
    // attachment. The runner's next barrier waits for that write.
    vkt::TargetWrite target_after(const vkt::Frame& frame) const override {
        if (!raster_) return vkt::drawn_by_colour_output;
        return raster_->resolves(frame) ? vkt::stored_by_compute : vkt::written_by_transfer;
    }
    // [/layout-after]

private:
    // Chapter 18's scene and keys, --raster and --verify, and the tuning.
    void read_options(const vkt::Context& context) {
        tuning_ = ch20::Tuning::for_device(context.properties);
        const auto& options = context.options;
        const nd::SceneChoice choice = nd::scene_choice(options);
        scene_name_ = choice.scene;
        still_ = choice.still;
        verify_ = options.has("--verify");
        verify_raster_ = verify_ && options.text("--verify") == "raster";
        scene_ = nd::make_scene(choice.scene, choice.n, still_);
        raster_name_ = options.text("--raster");
        if (raster_name_ == "auto") {  // the tuning's choice for this device and scene
            raster_name_ =
                tuning_.auto_raster(scene_.line_count(), ch20::BinnedRaster::available(context));
            raster_chosen_ = true;
        }
        binned_raster_ = raster_name_ == "binned";
        if (binned_raster_) ch20::BinnedRaster::check_device(context);
        keys_ = nd::Controls(choice.n, choice.orthographic ? nd::Projection::orthographic
                                                           : nd::Projection::perspective);
    }

    // [layouts]
    // Sets 0 to 2 (layouts.hpp), each pass's own, and the push constants.
    void create_layouts() {
        using ch20::TransformPass, ch20::ComputeRaster, ch20::BinnedRaster;
        layouts_.transform = ch20::storage_set_layout(device_, TransformPass::binding_count);
        layouts_.raster = ch20::storage_set_layout(device_, ComputeRaster::binding_count);
        layouts_.bins = ch20::storage_set_layout(device_, BinnedRaster::binding_count);
        const VkPushConstantRange push_range{
            .stageFlags = ch20::push_stages, .offset = 0, .size = sizeof(Push)};
        const VkDescriptorSetLayout sets[] = {layouts_.transform, layouts_.raster, layouts_.bins};
        layouts_.pipeline = vkt::create_pipeline_layout(device_, sets, {&push_range, 1});
    }
    // [/layouts]

    void describe() const {
        std::fprintf(stderr,
                     "20_ndim_compute: %s scene, n = %d, %zu objects, %u vertices, %u lines per "
                     "frame, raster %s%s, eye at %.3g\n",
                     scene_name_.c_str(), scene_.dim, scene_.objects.size(),
                     transform_->vertex_total(), transform_->line_total(), raster_name_.c_str(),
                     raster_chosen_ ? " (auto)" : "", scene_.eye);
        std::fprintf(stderr, "20_ndim_compute: %s\n", tuning_.describe().c_str());
    }

    // [line-pipeline]
    // The projected vertices, 16 bytes each, straight from the storage
    // buffer the transform pass wrote.
    void create_line_pipeline(const vkt::Context& context) {
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
                                                    .layout = layouts_.pipeline,
                                                    .bindings = {&binding, 1},
                                                    .attributes = attributes,
                                                    .topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
                                                    .color_formats = {context.color_format}});
    }
    // [/line-pipeline]

    // --raster compute: the lines drawn by a compute pass instead
    // (compute_raster.hpp); --raster binned: the same, tile by tile
    // (binned_raster.hpp), into the compute one's pixels.
    void create_rasterisers(const vkt::Context& context) {
        if (raster_name_ == "graphics") return;
        raster_.emplace(context, tuning_, layouts_, transform_->ends(), transform_->line_total());
        if (binned_raster_) binned_.emplace(context, tuning_, layouts_, transform_->line_counts());
    }

    Push make_push(VkExtent2D extent) const {
        const float aspect = float(extent.width) / float(extent.height);
        return {{1.0f / (scene_.view_half_height * aspect), -1.0f / scene_.view_half_height},
                scene_.eye,
                keys_.projection == nd::Projection::orthographic ? 1u : 0u,
                uint32_t(scene_.objects.size()),
                transform_->line_total(),
                {extent.width, extent.height}};
    }

    // The pose pass and the transform pass, recorded into any command buffer.
    // The frame's order for a check's own submit: the pose pass, then (binned)
    // the boxes cleared with set 2 bound, then the transform pass. The pose
    // pass binds a pipeline layout of its own, which unbinds set 2, so set 2
    // is bound after it, as record() does.
    void record_poses_and_transform(VkCommandBuffer cmd, uint32_t slot, const Push& push) const {
        poses_->record(cmd, slot, spin_time_, keys_);
        if (binned_) binned_->clear_boxes(cmd);
        transform_->record(cmd, layouts_.pipeline, slot, push);
    }

    // [verify]
    // --verify cpu: once the runner's loop is over and the GPU idle, run the
    // pose and transform passes alone on the last frame's scene, read the
    // projected vertices back and compare each with the CPU reference
    // (scene_state.hpp: vkt::ndim's per-plane transform_point and
    // project_to_2d, a different path from the matrix the GPU builds and
    // uses). Throws above the tolerance. (--verify raster: binned_raster.hpp.)
    void verify() override {
        if (!verify_) return;
        const uint32_t slot = last_.slot;
        const Push& push = last_.push;
        const VkBuffer projected = transform_->projected(slot);
        if (verify_raster_)
            return binned_->verify(*raster_, last_.extent, projected, [&](VkCommandBuffer cmd) {
                record_poses_and_transform(cmd, slot, push);
            });
        const VkDeviceSize bytes = transform_->vertex_total() * sizeof(Projected);
        vkt::Buffer host = vkt::create_host_buffer(gpu_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        vkt::one_time_submit(gpu_, [&](VkCommandBuffer cmd) {
            record_poses_and_transform(cmd, slot, push);
            vkt::buffer_barrier(cmd, projected, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                                VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkBufferCopy region{0, 0, bytes};
            vkCmdCopyBuffer(cmd, projected, host.buffer, 1, &region);
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
    std::string scene_name_, raster_name_;
    bool still_ = false, verify_ = false, verify_raster_ = false, binned_raster_ = false;
    bool raster_chosen_ = false;  // --raster auto chose raster_name_
    struct {
        uint32_t slot = 0;
        VkExtent2D extent{};
        Push push{};
    } last_;  // the last frame recorded
    nd::Scene scene_;
    nd::Controls keys_{4, nd::Projection::perspective};  // chapter 18's keys
    double last_time_ = 0.0;
    float spin_time_ = 0.0f;
    ch20::Tuning tuning_;  // the passes' shapes for this device (tuning.hpp)
    ch20::Layouts layouts_;
    std::optional<ch20::TransformPass> transform_;
    std::optional<ch20::PosePass> poses_;
    vkt::Pipeline lines_;
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
    // Each raster path writes the target first in its own way: the runner
    // hands it over untouched, and each path makes the first barrier itself.
    spec.target_layout = VK_IMAGE_LAYOUT_UNDEFINED;
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
                     "pass tile by tile; auto: the fastest for this device and scene",
             .default_value = "auto",
             .choices = {"auto", "graphics", "compute", "binned"}},
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
