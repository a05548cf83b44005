// Chapter 29: queues and timelines. Chapter 23's bloom (a chain of compute
// dispatches) moves to a queue of its own, from a family that computes but
// cannot draw where the device has one, and runs there while the graphics
// queue draws the next frame's scene. The images the two queues share change
// hands by queue-family ownership transfers (a release barrier on one queue,
// an acquire barrier on the other), and three timeline semaphores, one
// counter each for scenes, blooms and finished frames, order the queues and
// pace the host, where chapter 03 used a fence per frame and binary
// semaphores. --queues single draws the same frames on one queue, in one
// command buffer, as chapter 23 did: the picture must not change by a bit.

#include "overlap.hpp"
#include "queues.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/bloom.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"

#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace {

constexpr VkFormat hdr_format = VK_FORMAT_R16G16B16A16_SFLOAT;
// Scenes in flight: the one a tone map shows, the one drawn ahead, and a
// third the host records into meanwhile. With two, drawing scene N + 2
// would wait for tone map N, just submitted: the graphics queue would run
// dry every frame while the host woke up and submitted (the H200 showed it).
constexpr uint32_t slots = 3;

struct ScenePush {
    float width, height, time;
    uint32_t lamps;
};
struct TonemapPush {
    float bloom, levels;
};

class AsyncCompute : public vkt::Renderer {
public:
    explicit AsyncCompute(const vkt::Context& context)
        : gpu_(context.gpu()),
          compute_queue_(context.compute_queue),
          graphics_family_(context.queue_family),
          compute_family_(context.compute_family),
          async_(context.options.text("--queues") == "async"),
          lamps_(uint32_t(context.options.integer("--lamps"))),
          bloom_strength_(float(context.options.number("--bloom"))),
          radius_(uint32_t(context.options.integer("--bloom-radius"))),
          blooms_{vkt::Bloom(gpu_, context.chapter, radius_),
                  vkt::Bloom(gpu_, context.chapter, radius_),
                  vkt::Bloom(gpu_, context.chapter, radius_)},
          scene_done_(ch29::create_timeline(gpu_.device)),
          bloom_done_(ch29::create_timeline(gpu_.device)),
          frame_done_(ch29::create_timeline(gpu_.device)) {
        // [families]
        // Where the bloom runs, said once: the families the device gave us.
        if (!async_)
            std::fprintf(stderr,
                         "29_async_compute: --queues single: scene, bloom and tone map in "
                         "one command buffer on the graphics queue (family %u)\n",
                         graphics_family_);
        else if (compute_family_ != graphics_family_)
            std::fprintf(stderr,
                         "29_async_compute: --queues async: the bloom on a queue of "
                         "family %u (compute only), the scene and tone map on family %u; "
                         "images change family by release and acquire barriers\n",
                         compute_family_, graphics_family_);
        else
            std::fprintf(stderr,
                         "29_async_compute: --queues async: this device has one queue "
                         "family (%u): the bloom runs on the graphics queue, in submits "
                         "of its own ordered by the same timelines; nothing changes "
                         "family\n",
                         graphics_family_);
        // [/families]
        // Command buffers of our own, a pool per queue family per slot.
        for (uint32_t s = 0; s < slots; ++s) {
            scene_pools_[s] = vkt::create_command_pool(gpu_.device, graphics_family_,
                                                       VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
            bloom_pools_[s] = vkt::create_command_pool(gpu_.device, compute_family_,
                                                       VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
            scene_cmds_[s] = allocate(scene_pools_[s]);
            bloom_cmds_[s] = allocate(bloom_pools_[s]);
        }
        uint32_t count = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(gpu_.physical, &count, nullptr);
        std::vector<VkQueueFamilyProperties> families(count);
        vkGetPhysicalDeviceQueueFamilyProperties(gpu_.physical, &count, families.data());
        const bool timed = families[graphics_family_].timestampValidBits > 0 &&
                           families[compute_family_].timestampValidBits > 0;
        overlap_ = ch29::Overlap(gpu_.device, slots,
                                 context.options.benchmark && timed && bloom_strength_ > 0.0f,
                                 context.properties.limits.timestampPeriod);

        // The scene pass and the tone map: full-screen triangles (chapter 16).
        const vkt::ShaderModule fullscreen =
            vkt::load_shader(gpu_.device, context.chapter, "fullscreen.vert");
        const vkt::ShaderModule lamps =
            vkt::load_shader(gpu_.device, context.chapter, "lamps.frag");
        const vkt::ShaderModule tonemap =
            vkt::load_shader(gpu_.device, context.chapter, "tonemap.frag");
        const VkPushConstantRange scene_range{VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ScenePush)};
        scene_layout_ = vkt::create_pipeline_layout(gpu_.device, {}, {&scene_range, 1});
        scene_pipeline_ =
            vkt::create_graphics_pipeline(gpu_.device, {.vertex = fullscreen,
                                                        .fragment = lamps,
                                                        .layout = scene_layout_,
                                                        .color_formats = {hdr_format}});
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
            {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr}};
        set_layout_ = vkt::create_descriptor_set_layout(gpu_.device, bindings);
        const VkPushConstantRange tonemap_range{VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                                sizeof(TonemapPush)};
        const VkDescriptorSetLayout layouts[] = {set_layout_};
        tonemap_layout_ = vkt::create_pipeline_layout(gpu_.device, layouts, {&tonemap_range, 1});
        tonemap_pipeline_ =
            vkt::create_graphics_pipeline(gpu_.device, {.vertex = fullscreen,
                                                        .fragment = tonemap,
                                                        .layout = tonemap_layout_,
                                                        .color_formats = {context.color_format}});
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * slots}};
        pool_ = vkt::create_descriptor_pool(gpu_.device, slots, sizes);
        for (VkDescriptorSet& set : sets_)
            set = vkt::allocate_descriptor_set(gpu_.device, pool_, set_layout_);
        hdr_sampler_ = vkt::create_sampler(gpu_.device, 0.0f);  // read by texelFetch only
        resize(context.extent);
    }

    void resize(VkExtent2D extent) override {  // the GPU is idle
        extent_ = extent;
        for (uint32_t s = 0; s < slots; ++s) {
            hdr_[s] = vkt::create_image_2d(
                gpu_.physical, gpu_.device, hdr_format, extent,
                VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                VK_IMAGE_ASPECT_COLOR_BIT);
            blooms_[s].resize(extent, hdr_[s].view);
            vkt::write_image_descriptor(gpu_.device, sets_[s], 0, hdr_[s].view, hdr_sampler_,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
            vkt::write_image_descriptor(gpu_.device, sets_[s], 1, blooms_[s].level0(),
                                        blooms_[s].sampler(), VK_IMAGE_LAYOUT_GENERAL);
        }
        ahead_.reset();  // a scene drawn ahead at the old size is gone with its image
    }

    void record(const vkt::Frame& frame) override {
        const uint64_t n = frame.index;
        const uint32_t s = uint32_t(n % slots);
        if (!async_) {
            wait_for_slot(s);
            draw_scene(frame.cmd, n);
            vkt::image_barrier(
                frame.cmd, hdr_[s].image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
            if (bloom_strength_ > 0.0f) {
                overlap_.mark(frame.cmd, s, ch29::Overlap::bloom_begin);
                blooms_[s].record(frame.cmd, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
                overlap_.mark(frame.cmd, s, ch29::Overlap::bloom_end);
            }
            draw_tonemap(frame, s);
            return;
        }
        // [ahead]
        // Frame N's tone map shows scene N, whose bloom is already on the
        // compute queue; first this frame's submit draws scene N + 1 on the
        // graphics queue, so that the bloom of N + 1 has graphics work to
        // run beside. Frame 0 (and the first after a resize) draws its own
        // scene first.
        if (ahead_ != n) draw_ahead(n);
        draw_ahead(n + 1);
        // [/ahead]
        // [acquire]
        // Take scene N's images back from the compute family: the HDR image
        // (only read there) and the bloom's chain (written there).
        if (bloom_strength_ > 0.0f && compute_family_ != graphics_family_) {
            ch29::ownership_barrier(
                frame.cmd, hdr_[s].image, 1, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, compute_family_, graphics_family_,
                VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
            ch29::ownership_barrier(frame.cmd, blooms_[s].image(), blooms_[s].levels(),
                                    VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                                    compute_family_, graphics_family_, VK_PIPELINE_STAGE_2_NONE, 0,
                                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        }
        // [/acquire]
        draw_tonemap(frame, s);
    }

    // [frame-semaphores]
    // The runner's submit of frame N (the tone map) waits until bloom N is
    // done, at the fragment shader that reads it, and counts the frame done.
    vkt::FrameSemaphores semaphores(const vkt::Frame& frame) override {
        const uint32_t s = uint32_t(frame.index % slots);
        frame_value_[s] = ++frames_;
        vkt::FrameSemaphores sync;
        if (async_)
            sync.wait.push_back({.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                                 .semaphore = bloom_done_,
                                 .value = bloom_value_[s],
                                 .stageMask = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT});
        sync.signal.push_back({.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO,
                               .semaphore = frame_done_,
                               .value = frame_value_[s],
                               .stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT});
        return sync;
    }
    // [/frame-semaphores]

    void verify() override {  // after the last frame, the GPU idle: the last times
        for (uint32_t s = 0; s < slots; ++s) overlap_.collect(s);
        overlap_.report(async_ ? "async" : "single");
    }

private:
    VkCommandBuffer allocate(VkCommandPool pool) const {
        const VkCommandBufferAllocateInfo info{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
            .commandPool = pool,
            .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
            .commandBufferCount = 1};
        VkCommandBuffer cmd;
        VKT_CHECK(vkAllocateCommandBuffers(gpu_.device, &info, &cmd));
        return cmd;
    }

    // [host-wait]
    // Before slot s's command buffers and images are used again, the frame
    // that last showed them must be over: the host waits on the timeline for
    // that frame's value. No fence to reset; a value already reached returns
    // at once.
    void wait_for_slot(uint32_t s) {
        const VkSemaphore semaphore = frame_done_;
        const VkSemaphoreWaitInfo wait{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO,
                                       .semaphoreCount = 1,
                                       .pSemaphores = &semaphore,
                                       .pValues = &frame_value_[s]};
        VKT_CHECK(vkWaitSemaphores(gpu_.device, &wait, UINT64_MAX));
        overlap_.collect(s);
    }
    // [/host-wait]

    // The scene pass of scene k into its slot's HDR image, timed.
    void draw_scene(VkCommandBuffer cmd, uint64_t k) {
        const uint32_t s = uint32_t(k % slots);
        overlap_.reset(cmd, s);
        overlap_.mark(cmd, s, ch29::Overlap::scene_begin);
        // Its last readers (a tone map, a bloom) are over: the timeline said so.
        vkt::image_barrier(cmd, hdr_[s].image, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        vkt::begin_colour_rendering(cmd, hdr_[s].view, extent_, VK_ATTACHMENT_LOAD_OP_DONT_CARE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_pipeline_);
        vkt::set_viewport_and_scissor(cmd, extent_);
        // The scene's clock is its index, so a scene drawn ahead knows its time.
        const ScenePush push{float(extent_.width), float(extent_.height), float(double(k) / 60.0),
                             lamps_};
        vkCmdPushConstants(cmd, scene_layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
        overlap_.mark(cmd, s, ch29::Overlap::scene_end);
    }

    // [draw-ahead]
    // Scene k on the graphics queue, then its bloom on the compute queue.
    void draw_ahead(uint64_t k) {
        const uint32_t s = uint32_t(k % slots);
        wait_for_slot(s);
        const VkCommandBuffer scene = scene_cmds_[s];
        VKT_CHECK(vkResetCommandPool(gpu_.device, scene_pools_[s], 0));
        const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                             .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VKT_CHECK(vkBeginCommandBuffer(scene, &begin));
        draw_scene(scene, k);
        const bool bloom = bloom_strength_ > 0.0f;
        // Release the HDR image to the compute family, where the bloom runs
        // on one (the destination half is then ignored). Else the same call
        // is an ordinary barrier on this queue, for the bloom's and the tone
        // map's reads.
        const bool handover = bloom && compute_family_ != graphics_family_;
        ch29::ownership_barrier(
            scene, hdr_[s].image, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, graphics_family_,
            handover ? compute_family_ : graphics_family_,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            handover
                ? VK_PIPELINE_STAGE_2_NONE
                : VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            handover ? 0 : VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        VKT_CHECK(vkEndCommandBuffer(scene));
        ch29::submit(gpu_.queue, scene, VK_NULL_HANDLE, 0, VK_PIPELINE_STAGE_2_NONE, scene_done_,
                     ++scenes_);

        bloom_value_[s] = ++blooms_done_;
        if (!bloom) {
            // No bloom to wait for: the host itself moves the counter that
            // the tone map waits on, and nothing is submitted.
            const VkSemaphoreSignalInfo signal{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_SIGNAL_INFO,
                                               .semaphore = bloom_done_,
                                               .value = bloom_value_[s]};
            VKT_CHECK(vkSignalSemaphore(gpu_.device, &signal));
            ahead_ = k;
            return;
        }
        const VkCommandBuffer cmd = bloom_cmds_[s];
        VKT_CHECK(vkResetCommandPool(gpu_.device, bloom_pools_[s], 0));
        VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
        // Acquire the HDR image: the release's twin, read by the bloom's first dispatch.
        if (compute_family_ != graphics_family_)
            ch29::ownership_barrier(cmd, hdr_[s].image, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, graphics_family_,
                                    compute_family_, VK_PIPELINE_STAGE_2_NONE, 0,
                                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        overlap_.mark(cmd, s, ch29::Overlap::bloom_begin);
        // The chain starts UNDEFINED each time: its old contents, which the
        // graphics family last held, are thrown away, so they need no transfer.
        blooms_[s].record(cmd, VK_PIPELINE_STAGE_2_NONE);
        overlap_.mark(cmd, s, ch29::Overlap::bloom_end);
        // Release both images to the graphics family for the tone map.
        ch29::ownership_barrier(cmd, hdr_[s].image, 1, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, compute_family_,
                                graphics_family_, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                                VK_PIPELINE_STAGE_2_NONE, 0);
        ch29::ownership_barrier(cmd, blooms_[s].image(), blooms_[s].levels(),
                                VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL, compute_family_,
                                graphics_family_, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_NONE, 0);
        VKT_CHECK(vkEndCommandBuffer(cmd));
        ch29::submit(compute_queue_, cmd, scene_done_, scenes_,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, bloom_done_, bloom_value_[s]);
        ahead_ = k;
    }
    // [/draw-ahead]

    // The tone map of slot s's scene into the frame's target (the runner's
    // command buffer), timed.
    void draw_tonemap(const vkt::Frame& frame, uint32_t s) {
        overlap_.mark(frame.cmd, s, ch29::Overlap::tonemap_begin);
        vkt::begin_colour_rendering(frame.cmd, frame.target_view, frame.extent,
                                    VK_ATTACHMENT_LOAD_OP_DONT_CARE);
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tonemap_pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tonemap_layout_, 0, 1,
                                &sets_[s], 0, nullptr);
        const TonemapPush push{bloom_strength_, float(blooms_[s].levels())};
        vkCmdPushConstants(frame.cmd, tonemap_layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push,
                           &push);
        vkCmdDraw(frame.cmd, 3, 1, 0, 0);
        vkCmdEndRendering(frame.cmd);
        overlap_.mark(frame.cmd, s, ch29::Overlap::tonemap_end);
        overlap_.complete(s);
    }

    vkt::Gpu gpu_;
    VkQueue compute_queue_;
    uint32_t graphics_family_, compute_family_;
    bool async_;
    uint32_t lamps_;
    float bloom_strength_;
    uint32_t radius_;  // the bloom's tent: its compute work grows as (2 radius + 1)^2
    VkExtent2D extent_{};
    std::array<vkt::Bloom, slots> blooms_;
    std::array<vkt::Image, slots> hdr_;
    std::array<VkDescriptorSet, slots> sets_{};
    vkt::Sampler hdr_sampler_;
    vkt::PipelineLayout scene_layout_, tonemap_layout_;
    vkt::Pipeline scene_pipeline_, tonemap_pipeline_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::array<vkt::CommandPool, slots> scene_pools_, bloom_pools_;
    std::array<VkCommandBuffer, slots> scene_cmds_{}, bloom_cmds_{};
    // [counters]
    // The three timelines, and how far each has been asked to count: scenes
    // drawn, blooms done, frames shown. Per slot, the values its last bloom
    // and its last frame signal.
    vkt::Semaphore scene_done_, bloom_done_, frame_done_;
    uint64_t scenes_ = 0, blooms_done_ = 0, frames_ = 0;
    std::array<uint64_t, slots> bloom_value_{}, frame_value_{};
    // [/counters]
    std::optional<uint64_t> ahead_;  // the last scene drawn ahead
    ch29::Overlap overlap_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "29_async_compute", .title = "29 - Queues and timelines"};
    // Timeline semaphores; maintenance4 for the bloom's shaders (chapter 23);
    // and a queue of a compute-only family where the device has one.
    spec.requirements.features = {VKT_FEATURE_12(timelineSemaphore), VKT_FEATURE_13(maintenance4)};
    spec.requirements.compute_family = true;
    spec.options = {
        {.name = "--queues",
         .type = vkt::OptionType::choice,
         .value_name = "single|async",
         .help = "the bloom in the graphics queue's command buffer, or on a compute queue",
         .default_value = "async",
         .choices = {"single", "async"}},
        {.name = "--lamps",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "bright lamps in the scene: the graphics work of a frame",
         .default_value = "48",
         .min = 1,
         .max = 4096},
        {.name = "--bloom",
         .type = vkt::OptionType::number,
         .value_name = "X",
         .help = "how much bloom is mixed in: 0 (none, and no compute work) to 1",
         .default_value = "0.5",
         .min = 0,
         .max = 1},
        {.name = "--bloom-radius",
         .type = vkt::OptionType::integer,
         .value_name = "R",
         .help = "the bloom's tent, in texels of each level: the compute work of a frame",
         .default_value = "1",
         .min = 1,
         .max = 64},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<AsyncCompute>(context);
    });
}
