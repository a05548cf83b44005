// Chapter 28: GPU-driven culling.
//
// A field of --instances N shapes (100,000 by default: tens of millions of
// triangles) where the CPU records the same few commands every frame, and
// the GPU decides what to draw:
//
// - A compute pass (cull.comp) tests every instance's bounding box against
//   the view frustum and appends a VkDrawIndexedIndirectCommand for each
//   that survives to a list in a buffer, counting them with an atomic.
// - vkCmdDrawIndexedIndirectCount draws the list: the GPU reads how many
//   commands there are from a buffer too, so the CPU never learns it.
// - --cull occlusion adds two-phase occlusion culling: draw first what was
//   seen last frame (the early pass), build a depth pyramid from that depth
//   (pyramid.hpp), test everything in the frustum against it (the late
//   pass), and draw what is seen now and was not drawn early.
//
// - --path task draws with chapter 26's task and mesh shaders instead: a
//   task workgroup makes the same test for 32 instances and launches mesh
//   workgroups for the meshlets of those it keeps (task_path.hpp). Its
//   --view culled adds a pass from a second camera that launches every
//   meshlet, coloured by why the tests for the first would cull it.
//
// The counts are read back after the last frame and checked against the
// CPU's own frustum test (scene.hpp).

#include "draw_pass.hpp"
#include "pyramid.hpp"
#include "scene.hpp"
#include "task_path.hpp"

#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/upload.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

using ch28::Push;

enum Cull : uint32_t { cull_none, cull_frustum, cull_occlusion };
enum List : uint32_t { early_list, late_list, culled_list };
constexpr uint32_t kCullGroup = 64;  // cull.comp's local_size_x

class GpuCulling : public vkt::Renderer {
public:
    explicit GpuCulling(const vkt::Context& context)
        : gpu_(context.gpu()), extent_(context.extent) {
        const std::string cull = context.options.text("--cull"),
                          view = context.options.text("--view");
        mode_ = cull == "none" ? cull_none : cull == "frustum" ? cull_frustum : cull_occlusion;
        show_pyramid_ = view == "pyramid";
        show_culled_ = view == "culled" && context.options.text("--path") == "indirect";
        show_level_ = uint32_t(context.options.integer("--level"));
        count_ = uint32_t(context.options.integer("--instances"));
        const bool task = context.options.text("--path") == "task";
        stages_ = ch28::kStages |
                  (task ? VK_SHADER_STAGE_TASK_BIT_EXT | VK_SHADER_STAGE_MESH_BIT_EXT : 0);
        culler_ =
            task ? VK_PIPELINE_STAGE_2_TASK_SHADER_BIT_EXT : VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

        // The meshes in one vertex and index buffer, and cut into meshlets
        // (task_path.hpp); the instances, the floor last.
        vkt::shapes::MeshBuilder builder;
        std::vector<ch28::Mesh> meshes = ch28::make_meshes(builder);
        const vkt::Meshlets meshlets = ch28::make_meshlets(builder, meshes);
        instances_ = ch28::make_instances(count_, meshes);
        floor_ = meshes[ch28::floor_mesh].range;
        uint64_t triangles = 0;
        for (uint32_t i = 0; i < count_; ++i)
            triangles += meshes[uint32_t(instances_[i].box_half.w)].range.index_count / 3;
        std::vector<uint32_t> mesh_table;
        for (const ch28::Mesh& mesh : meshes)
            mesh_table.insert(mesh_table.end(), {mesh.range.first_index, mesh.range.index_count,
                                                 mesh.first_meshlet, mesh.meshlet_count});
        vertex_buffer_ = vkt::create_device_buffer(
            gpu_, builder.vertices.data(), builder.vertices.size() * sizeof(vkt::shapes::Vertex),
            VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ = vkt::create_device_buffer(gpu_, builder.indices.data(),
                                                  builder.indices.size() * sizeof(uint16_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
        instance_buffer_ = vkt::create_device_buffer(
            gpu_, instances_.data(), instances_.size() * sizeof(ch28::Instance), storage);
        mesh_buffer_ = vkt::create_device_buffer(gpu_, mesh_table.data(),
                                                 mesh_table.size() * sizeof(uint32_t), storage);

        // [buffers]
        // Three lists of commands, each long enough for every instance; the
        // counts, host-visible so that verify() reads the last frame's; one
        // word per instance: seen by the last late pass (none at first).
        draw_buffer_ = vkt::create_buffer(
            gpu_.physical, gpu_.device,
            3 * VkDeviceSize(count_) * sizeof(VkDrawIndexedIndirectCommand),
            storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        count_buffer_ = vkt::create_host_buffer(
            gpu_, 16 * sizeof(uint32_t),
            storage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        std::memset(count_buffer_.mapped, 0, count_buffer_.size);
        const std::vector<uint32_t> unseen(count_, 0);
        visible_buffer_ = vkt::create_device_buffer(gpu_, unseen.data(),
                                                    unseen.size() * sizeof(uint32_t), storage);
        // [/buffers]

        depth_format_ = vkt::choose_depth_format(gpu_.physical);
        const bool offered = ch28::sampler_min_offered(
            gpu_.physical, context.features.has(VKT_FEATURE_12(samplerFilterMinmax)),
            depth_format_);
        const std::string reduce = context.options.text("--reduce");
        sampler_min_ = reduce == "sampler" || (reduce == "auto" && offered);
        if (sampler_min_ && !offered)
            throw vkt::Error(
                "--reduce sampler: this device offers no min reduction in its "
                "sampler for " +
                std::string(vkt::depth_format_name(depth_format_)) + " and R32_SFLOAT");
        chapter_ = context.chapter;
        set_ = ch28::make_culling_set(
            gpu_.device, stages_,
            {instance_buffer_.buffer, mesh_buffer_.buffer, draw_buffer_.buffer,
             count_buffer_.buffer, visible_buffer_.buffer});
        resize(extent_);  // the depth buffer and the pyramid, which set_ points at

        const VkDescriptorSetLayout set_layout = set_.layout;
        const VkPushConstantRange push{stages_, 0, sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(gpu_.device, {&set_layout, 1}, {&push, 1});
        vkt::ShaderModule cull_shader = vkt::load_shader(gpu_.device, context.chapter, "cull.comp");
        cull_pipeline_ = vkt::create_compute_pipeline(gpu_.device, cull_shader, layout_);
        pipelines_ = ch28::make_draw_pipelines(gpu_.device, chapter_, layout_, context.color_format,
                                               depth_format_);
        if (task)
            task_ = std::make_unique<ch28::TaskPath>(
                gpu_, chapter_, builder, meshlets, set_.layout, stages_, context.color_format,
                depth_format_, ch28::meshlet_cull(context.options), view == "culled");

        std::fprintf(stderr,
                     "28_gpu_culling: %u instances of %u meshes (%zu meshlets), %llu triangles; "
                     "--cull %s, %s; the depth pyramid (%u levels from %ux%u) takes the min %s\n",
                     count_, uint32_t(ch28::mesh_count - 1), meshlets.meshlets.size(),
                     (unsigned long long)triangles, cull.c_str(),
                     task ? "task and mesh shaders" : "indirect draws", pyramid_->levels(),
                     pyramid_->size().width, pyramid_->size().height,
                     sampler_min_ ? "in the sampler (VK_SAMPLER_REDUCTION_MODE_MIN)"
                                  : "in the shader (four texel fetches)");
    }

    // The depth buffer is sampled too: the pyramid's level 0 reads it.
    void resize(VkExtent2D extent) override {
        extent_ = extent;
        depth_ = vkt::create_attachment_image(
            gpu_.physical, gpu_.device, depth_format_, extent_,
            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
            VK_IMAGE_ASPECT_DEPTH_BIT);
        pyramid_ =
            std::make_unique<ch28::DepthPyramid>(gpu_, chapter_, depth_.view, extent_, sampler_min_,
                                                 culler_ | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
        vkt::write_image_descriptor(gpu_.device, set_.set, 5, pyramid_->view(), pyramid_->sampler(),
                                    VK_IMAGE_LAYOUT_GENERAL);
    }

    void record(const vkt::Frame& frame) override {
        clip_from_world_ = ch28::camera(count_, frame.extent, frame.time);
        Push push{.clip_from_world = clip_from_world_,
                  .instance_count = count_,
                  .phase = 0,
                  .mode = mode_,
                  .list = early_list,
                  .viewport = {frame.extent.width, frame.extent.height},
                  .pyramid = {pyramid_->size().width, pyramid_->size().height},
                  .levels = pyramid_->levels(),
                  .show_level = std::min(show_level_, pyramid_->levels() - 1)};

        // [reset]
        // The last frame's draws have read the lists and the counts (one
        // queue: this barrier orders against everything submitted before);
        // then the counts start again from zero.
        // (culler_: the stage that culls, the compute or the task shader.)
        vkt::memory_barrier(
            frame.cmd,
            VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | culler_,
            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_READ_BIT |
                VK_ACCESS_2_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | culler_,
            VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_READ_BIT |
                VK_ACCESS_2_SHADER_WRITE_BIT);
        vkCmdFillBuffer(frame.cmd, count_buffer_.buffer, 0, VK_WHOLE_SIZE, 0);
        vkt::buffer_barrier(frame.cmd, count_buffer_.buffer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT, culler_,
                            VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT);
        // [/reset]

        if (!task_) {  // the task path culls as it draws
            auto scope = frame.gpu_scope("cull 1");
            cull(frame.cmd, push);
        }
        vkt::begin_depth_frame(frame.cmd, depth_.image);
        {
            auto scope = frame.gpu_scope("draw 1");
            draw(frame, push, VK_ATTACHMENT_LOAD_OP_CLEAR, {early_list});
        }
        if (mode_ == cull_occlusion) {
            // [two-phase]
            // The early pass's depth becomes the pyramid's level 0: it goes
            // from the depth attachment to a sampled image and back.
            vkt::image_barrier(frame.cmd, depth_.image, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
            {
                auto scope = frame.gpu_scope("pyramid");
                pyramid_->before_build(frame.cmd);
                pyramid_->build(frame.cmd);
            }
            vkt::image_barrier(frame.cmd, depth_.image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                               VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                   VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                   VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                               VK_IMAGE_ASPECT_DEPTH_BIT);
            // The late cull rewrites the counts and lists the early draws
            // read as indirect commands (or the early task shader wrote):
            // it waits for those reads and writes.
            vkt::memory_barrier(
                frame.cmd, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | culler_,
                VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT, culler_,
                VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT);
            push.phase = 1;
            push.list = show_culled_ ? culled_list : late_list;
            if (!task_) {
                auto scope = frame.gpu_scope("cull 2");
                cull(frame.cmd, push);
            }
            {
                auto scope = frame.gpu_scope("draw 2");
                if (show_culled_)
                    draw(frame, push, VK_ATTACHMENT_LOAD_OP_LOAD, {late_list, culled_list});
                else
                    draw(frame, push, VK_ATTACHMENT_LOAD_OP_LOAD, {late_list});
            }
            // [/two-phase]
        }
        if (task_ && task_->shows_fates()) {  // --view culled, the task path's (task_path.hpp)
            task_->before_fates(frame.cmd, push);
            push.phase = ch28::kFates;
            push.clip_from_world = ch28::camera(count_, frame.extent, frame.time, true);
            draw(frame, push, VK_ATTACHMENT_LOAD_OP_CLEAR, {early_list});
        }
        if (show_pyramid_)
            ch28::show_pyramid(frame.cmd, frame.target_view, frame.extent, pipelines_.pyramid,
                               layout_, stages_, set_.set, push);
    }

    // After the last frame: the GPU's counts beside the CPU's.
    void verify() override {
        const auto* counts = static_cast<const uint32_t*>(count_buffer_.mapped);
        const ch28::FrustumCount cpu = ch28::count_in_frustum(instances_, count_, clip_from_world_);
        const uint32_t drawn = counts[early_list] + counts[late_list];
        std::fprintf(stderr,
                     "28_gpu_culling: last frame: %u of %u instances in the frustum (the CPU "
                     "finds %u, and %u on its boundary), %u drawn (%u early + %u late), %u "
                     "occluded\n",
                     counts[3], count_, cpu.inside, cpu.boundary, drawn, counts[early_list],
                     counts[late_list], counts[4]);
        // [check]
        if (counts[3] < cpu.inside || counts[3] > cpu.inside + cpu.boundary)
            throw vkt::Error("the GPU found " + std::to_string(counts[3]) +
                             " instances in the frustum, the CPU " + std::to_string(cpu.inside) +
                             " (and " + std::to_string(cpu.boundary) + " on its boundary)");
        const uint32_t expected = mode_ == cull_none      ? count_
                                  : mode_ == cull_frustum ? counts[3]
                                                          : counts[3] - counts[4];
        // Occlusion: the early pass may draw what is since occluded, never
        // what left the frustum; the late pass only what is seen.
        if (mode_ == cull_occlusion
                ? (counts[late_list] > expected || drawn > counts[3] || counts[4] > counts[3])
                : drawn != expected)
            throw vkt::Error("the GPU drew " + std::to_string(drawn) + " instances, expected " +
                             (mode_ == cull_occlusion ? "at most " : "") +
                             std::to_string(expected));
        // [/check]
        if (task_) task_->report(counts);
    }

private:
    // [dispatch]
    // One invocation per instance; then the lists and counts are read as
    // indirect commands, the visibility by the next cull.
    void cull(VkCommandBuffer cmd, const Push& push) const {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, cull_pipeline_);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_.set, 0,
                                nullptr);
        vkCmdPushConstants(cmd, layout_, stages_, 0, sizeof(Push), &push);
        vkCmdDispatch(cmd, uint32_t(vkt::dispatch_count(count_, kCullGroup)), 1, 1);
        vkt::memory_barrier(
            cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
            VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_READ_BIT |
                VK_ACCESS_2_SHADER_WRITE_BIT);
    }
    // [/dispatch]

    // [draw]
    // The floor (early only), then each list: at most count_ commands, as
    // many as the count buffer says, 20 bytes apart. Or the task path's one
    // command for the pass.
    void draw(const vkt::Frame& frame, Push push, VkAttachmentLoadOp load,
              std::initializer_list<List> lists) const {
        ch28::begin_pass(frame.cmd, frame.target_view, depth_.view, frame.extent, load);
        const VkBuffer vertices = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertices, &offset);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1,
                                &set_.set, 0, nullptr);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        for (List list : lists) {
            push.list = list;
            vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              list == culled_list ? pipelines_.culled : pipelines_.shapes);
            vkCmdPushConstants(frame.cmd, layout_, stages_, 0, sizeof(Push), &push);
            if (list == early_list)
                vkCmdDrawIndexed(frame.cmd, floor_.index_count, 1, floor_.first_index, 0, count_);
            if (task_)
                task_->draw(frame.cmd, push);
            else
                vkCmdDrawIndexedIndirectCount(
                    frame.cmd, draw_buffer_.buffer,
                    VkDeviceSize(list) * count_ * sizeof(VkDrawIndexedIndirectCommand),
                    count_buffer_.buffer, list * sizeof(uint32_t), count_,
                    sizeof(VkDrawIndexedIndirectCommand));
        }
        vkCmdEndRendering(frame.cmd);
    }
    // [/draw]

    vkt::Gpu gpu_;
    VkExtent2D extent_;
    std::string chapter_;
    Cull mode_ = cull_occlusion;
    bool show_pyramid_ = false, show_culled_ = false, sampler_min_ = false;
    uint32_t show_level_ = 0, count_ = 0;
    VkShaderStageFlags stages_ = ch28::kStages;  // and the task path's
    VkPipelineStageFlags2 culler_ = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    std::vector<ch28::Instance> instances_;
    vkt::shapes::MeshRange floor_;
    glm::mat4 clip_from_world_{1.0f};  // the last frame's, for verify()
    vkt::Buffer vertex_buffer_, index_buffer_, instance_buffer_, mesh_buffer_;
    vkt::Buffer draw_buffer_, count_buffer_, visible_buffer_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    std::unique_ptr<ch28::DepthPyramid> pyramid_;
    ch28::CullingSet set_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline cull_pipeline_;
    ch28::DrawPipelines pipelines_;
    std::unique_ptr<ch28::TaskPath> task_;  // --path task only
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "28_gpu_culling", .title = "28 - GPU-driven culling"};
    // drawIndirectCount: vkCmdDrawIndexedIndirectCount; drawIndirectFirstInstance:
    // firstInstance names the instance; the depth barrier's layout (chapter 08);
    // maintenance4, as chapter 13: glslang writes a compute shader's workgroup
    // size as LocalSizeId.
    spec.requirements.features = {
        VKT_FEATURE_12(drawIndirectCount), VKT_FEATURE_10(drawIndirectFirstInstance),
        VKT_FEATURE_10(multiDrawIndirect), VKT_FEATURE_12(separateDepthStencilLayouts),
        VKT_FEATURE_13(maintenance4)};
    spec.requirements.optional_features = {VKT_FEATURE_12(samplerFilterMinmax)};
    spec.options = {
        {.name = "--instances",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "instances on the field (a square grid, every eighth row a wall)",
         .default_value = "100000",
         .min = 1,
         .max = 1000000},
        {.name = "--cull",
         .type = vkt::OptionType::choice,
         .help = "draw every instance, those in the frustum, or those not occluded either",
         .default_value = "occlusion",
         .choices = {"none", "frustum", "occlusion"}},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .help = "the picture, a level of the depth pyramid, or what is culled (in colours)",
         .default_value = "shaded",
         .choices = {"shaded", "pyramid", "culled"}},
        {.name = "--level",
         .type = vkt::OptionType::integer,
         .value_name = "L",
         .help = "--view pyramid: which level (the last if past it)",
         .default_value = "2",
         .min = 0,
         .max = 15},
        {.name = "--path",
         .type = vkt::OptionType::choice,
         .help = "draw lists by vkCmdDrawIndexedIndirectCount, or task and mesh shaders",
         .default_value = "indirect",
         .choices = {"indirect", "task"}},
        ch28::meshlet_cull_option(),
        {.name = "--reduce",
         .type = vkt::OptionType::choice,
         .help = "how the pyramid takes the min: the sampler's where offered, or the shader's",
         .default_value = "auto",
         .choices = {"auto", "sampler", "shader"}},
    };
    spec.check_options = [&spec](const vkt::Options& options) {
        if (options.text("--view") != "shaded" && options.text("--cull") != "occlusion")
            throw vkt::UsageError("--view " + options.text("--view") +
                                  " needs --cull occlusion: only it builds a pyramid and "
                                  "occludes instances");
        // Run before any device is chosen: --path task makes the mesh shader
        // extension a requirement, and a device without it is refused by name.
        ch28::meshlet_cull(options);  // refused without --path task (and off with culled)
        if (options.text("--path") == "task") ch28::require_mesh_shaders(spec.requirements);
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<GpuCulling>(context);
    });
}
