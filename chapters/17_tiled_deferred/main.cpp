// Chapter 17: tiled deferred shading.
//
// Chapter 16's scene and G-buffer, under thousands of moving point lights,
// which a compute pass moves each frame (light_motion.hpp).
// Chapter 16's lighting pass tests every light at every pixel; here a compute
// pass first cuts the screen into 16 x 16 pixel tiles, finds each tile's depth
// range, and keeps for each tile only the lights whose spheres may touch the
// tile's small frustum. The lighting then loops over its tile's list alone:
//
//   --shade fragment: the compute pass writes the lists to a buffer and a
//                     full-screen triangle lights the pixels (three passes);
//   --shade compute:  one dispatch culls and lights, the list never leaving
//                     shared memory; the result is copied to the target;
//   --shade lists:    as fragment, but the lighting is a compute pass, one
//                     invocation per pixel (the experiment of the
//                     performance part: what the fragment launch costs).
//
// Which lights a tile tests is the second choice:
//
//   --cull tiled:  every light (the first step: tiles x lights tests);
//   --cull binned: only the candidates in the tile's bin; three compute
//                  passes before the tile pass put each light into the bins
//                  of the tiles its sphere may cover (the second step).
//
// --view heat shows how many lights each tile kept. --verify brute compares
// both tiled results with chapter 16's brute-force lighting pass; --verify
// bins compares the binned lists and pictures with the tiled ones.
//
// Where the parts live: chapter 16's G-buffer pass in vkt/scene/gbuffer_pass.hpp;
// the lights' motion in light_motion.hpp; the binning in bin_pass.hpp; the tile pass (cull, or cull
// and shade) in tile_pass.hpp; the fragment lighting pass in lighting_pass.hpp; the checks in
// verify_brute.hpp and verify_bins.hpp; the frame's data and the frame here.

#include "bin_pass.hpp"
#include "light_motion.hpp"
#include "lighting_pass.hpp"
#include "tile_pass.hpp"
#include "verify_bins.hpp"
#include "verify_brute.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/gbuffer_pass.hpp"
#include "vkt/scene/moving_lights.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace vkt::deferred;  // chapter 16's blocks, scene and G-buffer pass
using ch17::TileStats;

// 32 MiB of lights per frame in flight, a quarter of the smallest
// maxStorageBufferRange a device may have (2^27 bytes).
constexpr uint32_t max_lights = 1048576;
// --verify renders into float targets, so that nothing is clamped or rounded.
constexpr VkFormat verify_format = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr int32_t view_heat = 5;  // VIEW_HEAT; VIEW_LIT is chapter 16's view_lit

class TiledDeferred : public vkt::Renderer {
public:
    explicit TiledDeferred(const vkt::Context& context)
        : gpu_(context.gpu()),
          device_(context.device),
          compute_(context.options.text("--shade") == "compute"),
          lists_(context.options.text("--shade") == "lists"),
          binned_(context.options.text("--cull") == "binned"),
          verify_(context.options.has("--verify") ? context.options.text("--verify") : ""),
          view_(context.options.text("--view") == "heat" ? view_heat : view_lit),
          light_count_(uint32_t(context.options.integer("--lights"))),
          frame_layout_(create_frame_layout(device_)),
          screen_layout_(create_screen_layout(device_)),
          layout_(create_layout(device_, frame_layout_, screen_layout_)),
          scene_(gpu_, frame_layout_),
          // Read by the fragment lighting pass and by the tile pass, in compute.
          gbuffer_(
              context, scene_,
              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT),
          tiles_(context, layout_),
          bins_(context, layout_, light_count_, uint32_t(context.options.integer("--bin-budget"))),
          lighting_(context, layout_, verify_.empty() ? VK_FORMAT_UNDEFINED : verify_format),
          moving_(light_count_) {
        std::fprintf(stderr, "17_tiled_deferred: %u light%s, shade %s, view %s, cull %s\n",
                     light_count_, light_count_ == 1 ? "" : "s",
                     context.options.text("--shade").c_str(),
                     context.options.text("--view").c_str(), binned_ ? "binned" : "tiled");
        create_frame_data(context.frames_in_flight,
                          context.properties.limits.maxStorageBufferRange);
        motion_.emplace(context, moving_, lights_);
        resize(context.extent);
    }

    ~TiledDeferred() override {
        // Only the counting: the run is over, no bins to grow (which may throw).
        for (uint32_t slot = 0; slot < stats_.size(); ++slot) count_stats(slot);
        if (tiles_seen_ > 0)
            std::fprintf(stderr,
                         "17_tiled_deferred: lights per lit tile: mean %.1f, most %u (a list "
                         "holds %u); tiles overflowed: %u\n",
                         double(lights_seen_) / double(tiles_seen_), most_lights_,
                         ch17::max_tile_lights, overflowed_);
        if (binned_ && tiles_seen_ > 0)
            std::fprintf(stderr,
                         "17_tiled_deferred: bins: most candidates in a frame %u (budget %u), "
                         "in a lit tile %u; frames that dropped candidates: %u\n",
                         most_entries_, bins_.capacity(), most_candidates_, dropped_frames_);
    }

    // Everything as large as the screen: the G-buffer, the tiles' lists and
    // bins, the compute path's output; set 1 points at them.
    void resize(VkExtent2D extent) override {
        gbuffer_.resize(extent);
        tiles_.resize(extent);
        bins_.resize(extent);
        gbuffer_.write_descriptors(screen_set_);
        tiles_.write_descriptors(screen_set_);
        bins_.write_descriptors(screen_set_);
    }

    // [frame]
    void record(const vkt::Frame& frame) override {
        read_stats(frame.slot);  // the last use of this slot is finished
        const float t = float(frame.time);
        update(frame.slot, frame.extent, t);
        last_ = {frame.slot, frame.extent, t};  // what verify() checks
        const VkCommandBuffer cmd = frame.cmd;
        const ch17::PassSets sets = pass_sets(frame.slot);
        {
            auto scope = frame.gpu_scope("move");  // every light to where it is at t
            motion_->record(cmd, frame.slot, t);
        }
        {
            auto scope = frame.gpu_scope("gbuffer");
            gbuffer_.record(cmd, sets.frame_set, frame.extent, objects_);
        }
        if (binned_) {
            auto scope = frame.gpu_scope("bin");  // count, scan, fill
            bins_.record(cmd, sets);
        }
        if (compute_) {
            {
                auto scope = frame.gpu_scope("shade");  // cull and shade, one dispatch
                tiles_.shade(cmd, sets, frame.extent, view_, binned_);
            }
            auto scope = frame.gpu_scope("copy");
            tiles_.copy_to_target(cmd, frame.target, frame.extent, frame.target_ready);
        } else {
            {
                auto scope = frame.gpu_scope("cull");
                tiles_.cull(cmd, sets, frame.extent, view_, binned_);
            }
            if (lists_) {
                {
                    auto scope = frame.gpu_scope("lighting");  // in compute
                    lighting_.dispatch(cmd, sets, frame.extent, tiles_, view_);
                }
                auto scope = frame.gpu_scope("copy");
                tiles_.copy_to_target(cmd, frame.target, frame.extent, frame.target_ready);
                return;
            }
            auto scope = frame.gpu_scope("lighting");
            vkt::image_barrier(cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED,  // see target_layout
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, frame.target_ready,
                               VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
            lighting_.draw(cmd, sets, frame.extent, frame.target_view, ch17::LightingPass::tiled,
                           &view_, sizeof view_);
        }
    }
    // [/frame]

    // The shading in compute ends with a blit into the target, the fragment
    // pass with its drawing: the runner's next barrier starts where each left it.
    vkt::TargetWrite target_after(const vkt::Frame&) const override {
        return compute_ || lists_ ? vkt::written_by_transfer : vkt::drawn_by_colour_output;
    }

private:
    // Set 0, one per frame in flight: uniforms, lights, tile statistics.
    static vkt::DescriptorSetLayout create_frame_layout(VkDevice device) {
        const VkShaderStageFlags all =
            VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, all, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, all, nullptr},
            {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
        };
        return vkt::create_descriptor_set_layout(device, bindings);
    }

    // Set 1, one for all: the G-buffer (bindings 0..3, as chapter 16's, with
    // its helper), the tiles' counts and lists, the compute output, and the
    // binning's buffers (7..11: the lights' spheres and rectangles, the bins).
    static vkt::DescriptorSetLayout create_screen_layout(VkDevice device) {
        const VkShaderStageFlags readers =
            VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
        const auto gbuffer = GBufferPass::bindings(readers);
        std::vector<VkDescriptorSetLayoutBinding> bindings(gbuffer.begin(), gbuffer.end());
        bindings.push_back({4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, readers, nullptr});
        bindings.push_back({5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, readers, nullptr});
        bindings.push_back(
            {6, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        for (uint32_t binding = 7; binding <= 11; ++binding)
            bindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
        return vkt::create_descriptor_set_layout(device, bindings);
    }

    // One layout for every pass after the G-buffer: sets 0 and 1, and 16
    // bytes of push constants (chapter 16's LightingPush is the largest).
    static vkt::PipelineLayout create_layout(VkDevice device, VkDescriptorSetLayout frame,
                                             VkDescriptorSetLayout screen) {
        const VkPushConstantRange range{VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                                        0, sizeof(LightingPush)};
        const VkDescriptorSetLayout sets[] = {frame, screen};
        return vkt::create_pipeline_layout(device, sets, {&range, 1});
    }

    // Chapter 07's per-frame buffers and sets, with chapter 07's helpers, as
    // chapter 16 writes them; the statistics are new.
    void create_frame_data(uint32_t slots, uint32_t max_storage_range) {
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slots},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2 * slots + 7},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
        pool_ = vkt::create_descriptor_pool(device_, slots + 1, sizes);
        const VkDeviceSize lights_size = VkDeviceSize{light_count_} * sizeof(vkt::PointLight);
        if (lights_size > max_storage_range)
            throw vkt::Error("--lights " + std::to_string(light_count_) + ": " +
                             std::to_string(lights_size >> 20) + " MiB of lights, more than " +
                             "this device's maxStorageBufferRange (" +
                             std::to_string(max_storage_range >> 20) + " MiB)");
        for (uint32_t i = 0; i < slots; ++i) {
            uniforms_.push_back(vkt::create_host_buffer(gpu_, sizeof(FrameUniforms),
                                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            // Written by the motion pass, read by the others; --verify copies it out.
            lights_.push_back(vkt::create_buffer(
                gpu_.physical, device_, lights_size,
                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT));
            stats_.push_back(vkt::create_host_buffer(gpu_, sizeof(TileStats),
                                                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            std::memset(stats_[i].mapped, 0, sizeof(TileStats));
            stats_pending_.push_back(false);
            frame_sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, frame_layout_));
            const vkt::Buffer* buffers[] = {&uniforms_[i], &lights_[i], &stats_[i]};
            for (uint32_t b = 0; b < 3; ++b)
                vkt::write_buffer_descriptor(
                    device_, frame_sets_[i], b,
                    b == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                    buffers[b]->buffer, 0, VK_WHOLE_SIZE);
        }
        screen_set_ = vkt::allocate_descriptor_set(device_, pool_, screen_layout_);
    }

    ch17::PassSets pass_sets(uint32_t slot) const {
        return {layout_, frame_sets_[slot], screen_set_, stats_[slot].buffer};
    }

    // Chapter 16's frame: the same camera, materials and shapes; the lights
    // are the motion pass's.
    void update(uint32_t slot, VkExtent2D extent, float t) {
        const FrameUniforms frame =
            frame_uniforms(float(extent.width) / float(extent.height), light_count_);
        std::memcpy(uniforms_[slot].mapped, &frame, sizeof frame);
        objects_ = make_objects(t);
    }

    // What the slot's last frame counted (it is finished); the bins grow
    // for the next frames if its fill dropped candidates.
    void read_stats(uint32_t slot) {
        const uint32_t needed = count_stats(slot);
        if (binned_ && bins_.grow(needed)) bins_.write_descriptors(screen_set_);
    }

    // The slot's counts, added to the run's and zeroed; returns the
    // candidates its bins needed (0 when it has not drawn yet).
    uint32_t count_stats(uint32_t slot) {
        if (!stats_pending_[slot]) {
            stats_pending_[slot] = true;  // the coming frame will count
            return 0;
        }
        TileStats stats{};
        std::memcpy(&stats, stats_[slot].mapped, sizeof stats);
        std::memset(stats_[slot].mapped, 0, sizeof stats);
        overflowed_ = std::max(overflowed_, stats.overflowed_tiles);
        most_lights_ = std::max(most_lights_, stats.most_lights);
        lights_seen_ += stats.total_lights;
        tiles_seen_ += stats.lit_tiles;
        most_entries_ = std::max(most_entries_, stats.binned_entries);
        most_candidates_ = std::max(most_candidates_, stats.most_candidates);
        // Candidates the fill dropped: counted, and the bins grow for the next frames.
        if (stats.binned_entries > stats.binned_budget) ++dropped_frames_;
        return stats.binned_entries;
    }

    // [verify]
    // Once the runner's loop is over and the GPU idle, on the last frame's
    // scene. Both checks first compare the lights the GPU moved to that
    // frame's time with the CPU's (light_motion.hpp). --verify brute
    // (verify_brute.hpp): the frame once more, into float images: chapter
    // 16's lighting pass over every light, the tiled fragment pass and the
    // tiled compute pass (culling as --cull says), from one G-buffer.
    // --verify bins (verify_bins.hpp): the lists and pictures of --cull
    // tiled and --cull binned, from one G-buffer.
    void verify() override {
        if (verify_.empty()) return;
        const uint32_t slot = last_.slot;
        const VkExtent2D e = last_.extent;
        const float t = last_.time;
        count_stats(slot);  // the last frame's counts, before the checks count their own
        motion_->verify(slot, t, moving_);
        const ch17::PassSets sets = pass_sets(slot);
        const LightingPush everything{view_lit, 0, light_count_, 1.0f};
        const int32_t lit = view_lit;
        using Lighting = ch17::LightingPass;
        auto gbuffer_and_bins = [&](VkCommandBuffer cmd) {
            motion_->record(cmd, slot, t);
            gbuffer_.record(cmd, sets.frame_set, e, objects_);
            bins_.record(cmd, sets);  // whichever --cull: --verify bins needs both
        };
        auto tiled_fragment = [&](VkCommandBuffer cmd, VkImageView target, bool binned) {
            tiles_.cull(cmd, sets, e, lit, binned);
            lighting_.draw(cmd, sets, e, target, Lighting::tiled_float, &lit, sizeof lit);
        };
        auto tiled_compute = [&](VkCommandBuffer cmd, bool binned) {
            tiles_.shade(cmd, sets, e, lit, binned);
        };
        if (verify_ == "bins") {
            ch17::verify_bins(gpu_, e, light_count_, tiles_, stats_[slot].mapped, gbuffer_and_bins,
                              tiled_fragment, tiled_compute);
            return;
        }
        ch17::verify_brute(
            gpu_, e, light_count_, tiles_.shaded(), stats_[slot].mapped,
            {gbuffer_and_bins,
             [&](VkCommandBuffer cmd, VkImageView target) {
                 lighting_.draw(cmd, sets, e, target, Lighting::brute_float, &everything,
                                sizeof everything);
             },
             [&](VkCommandBuffer cmd, VkImageView target) { tiled_fragment(cmd, target, binned_); },
             [&](VkCommandBuffer cmd) { tiled_compute(cmd, binned_); }});
    }
    // [/verify]

    vkt::Gpu gpu_;
    VkDevice device_;
    bool compute_, lists_, binned_;
    std::string verify_;  // "", "brute" or "bins"
    int32_t view_;
    uint32_t light_count_;
    struct {
        uint32_t slot = 0;
        VkExtent2D extent{};
        float time = 0.0f;
    } last_;  // the last frame recorded
    // Declared in the order they are made: each part needs those above it.
    vkt::DescriptorSetLayout frame_layout_, screen_layout_;
    vkt::PipelineLayout layout_;
    SceneMeshes scene_;
    GBufferPass gbuffer_;
    ch17::TilePass tiles_;
    ch17::BinPass bins_;
    ch17::LightingPass lighting_;
    MovingLights moving_;  // the lights' homes and paths; the CPU reference
    vkt::DescriptorPool pool_;
    std::vector<vkt::Buffer> uniforms_, lights_, stats_;  // [slot]
    std::optional<ch17::LightMotion> motion_;             // made once lights_ is
    std::vector<bool> stats_pending_;                     // [slot]
    std::vector<VkDescriptorSet> frame_sets_;             // [slot]
    VkDescriptorSet screen_set_ = VK_NULL_HANDLE;
    std::vector<Object> objects_;                // this frame's
    uint32_t overflowed_ = 0, most_lights_ = 0;  // over the run
    uint64_t lights_seen_ = 0, tiles_seen_ = 0;
    uint32_t most_entries_ = 0, most_candidates_ = 0, dropped_frames_ = 0;  // --cull binned
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "17_tiled_deferred", .title = "17 - tiled deferred"};
    // DEPTH_ATTACHMENT_OPTIMAL and DEPTH_READ_ONLY_OPTIMAL, as chapter 16; and
    // maintenance4, as chapter 13: glslang writes a compute shader's workgroup
    // size for Vulkan 1.3 as LocalSizeId, which needs it.
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts),
                                  VKT_FEATURE_13(maintenance4)};
    // --shade compute and lists copy their shaded image into the frame.
    spec.transfers_into_target = true;
    // Untouched: the compute paths blit into it, the fragment path draws.
    spec.target_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    spec.options = {
        {.name = "--shade",
         .type = vkt::OptionType::choice,
         .value_name = "PASS",
         .help = "fragment (a compute pass writes light lists, a fragment pass lights), "
                 "compute (one dispatch culls and lights) or lists (as fragment, the lighting "
                 "in compute)",
         .default_value = "fragment",
         .choices = {"fragment", "compute", "lists"}},
        {.name = "--cull",
         .type = vkt::OptionType::choice,
         .value_name = "HOW",
         .help = "binned (each light into the bins of the tiles it may touch; each tile tests "
                 "its bin) or tiled (each tile tests every light)",
         .default_value = "binned",
         .choices = {"binned", "tiled"}},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "lit, or heat: the number of lights each tile kept",
         .default_value = "lit",
         .choices = {"lit", "heat"}},
        {.name = "--lights",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many point lights, 1 to 1048576",
         .default_value = "1024",
         .min = 1,
         .max = double(max_lights)},
        {.name = "--bin-budget",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "--cull binned: room for N candidates in all bins at the start, 0: 4 per "
                 "light or 64 per tile, whichever is more (it grows when a frame needs more)",
         .default_value = "0",
         .min = 0,
         .max = double(1u << 30)},
        {.name = "--verify",
         .type = vkt::OptionType::choice,
         .value_name = "CHECK",
         .help = "on the last frame, brute: both tiled paths against brute-force lighting; "
                 "bins: --cull binned's lists and pictures against --cull tiled's",
         .choices = {"brute", "bins"}},
    };
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<TiledDeferred>(context);
    });
}
