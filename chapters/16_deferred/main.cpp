// Chapter 16: deferred shading.
//
// The scene of a few shapes on a floor, under many moving point lights, drawn
// in two passes. Pass 1 draws the geometry once and writes, for each pixel,
// what lighting needs to know about the visible surface into the G-buffer:
// base colour, normal, material parameters, and depth. Pass 2 draws one
// full-screen triangle and lights each pixel from the G-buffer, so every
// light is evaluated once per pixel, never for a hidden surface. --path
// forward draws the same scene the classic way, lighting each fragment as it
// is drawn, for comparison.
//
// Where the parts live (each reads top to bottom beside the book's page):
//   vkt/scene/gbuffer_pass.hpp  pass 1, its images and the barriers written out
//                               (common/scene, because chapter 17 draws it too)
//   lighting_pass.hpp           pass 2
//   forward_pass.hpp            the forward path
//   this file                   the frame's data, the frame, and --verify
//
// The lighting is chapter 12's (shaders/common/lighting.glsl, vkt/scene/lighting.hpp)
// with its windowed falloff; the lights live in a storage buffer, up to 65,536.

#include "forward_pass.hpp"
#include "lighting_pass.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/deferred_blocks.hpp"
#include "vkt/scene/deferred_scene.hpp"
#include "vkt/scene/deferred_verify.hpp"
#include "vkt/scene/gbuffer_pass.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace vkt::deferred;  // chapter 16's blocks, scene, G-buffer pass and checks

// Our own limit: 65,536 lights of 32 bytes are 2 MiB per frame in flight, far
// below maxStorageBufferRange (the specification promises at least 128 MiB).
constexpr uint32_t max_lights = 65536;
// --verify renders into float targets, so that nothing is clamped or rounded.
constexpr VkFormat verify_format = VK_FORMAT_R32G32B32A32_SFLOAT;
const char* const views[] = {"lit", "albedo", "normal", "material", "depth"};

// Flags that contradict each other are a usage error (exit status 2), found
// before any device is made.
void check_flags(const vkt::Options& options) {
    const bool forward = options.text("--path") == "forward";
    if (forward && options.text("--view") != "lit")
        throw vkt::UsageError("--view " + options.text("--view") +
                              " shows a G-buffer target: it needs --path deferred");
    if (forward && options.has("--verify"))
        throw vkt::UsageError("--verify renders both paths itself: leave out --path forward");
}

class Deferred : public vkt::Renderer {
public:
    explicit Deferred(const vkt::Context& context)
        : gpu_(context.gpu()),
          device_(context.device),
          forward_path_(context.options.text("--path") == "forward"),
          light_count_(uint32_t(context.options.integer("--lights"))),
          verify_(context.options.has("--verify") ? context.options.text("--verify") : ""),
          frame_layout_(create_frame_layout(context.device)),
          scene_(gpu_, frame_layout_),
          gbuffer_(context, scene_, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT),
          lighting_(context, frame_layout_, verify_.empty() ? VK_FORMAT_UNDEFINED : verify_format),
          forward_(context, scene_, verify_.empty() ? VK_FORMAT_UNDEFINED : verify_format) {
        const std::string view = context.options.text("--view");
        for (int32_t i = 0; i < 5; ++i)
            if (view == views[i]) view_ = i;
        std::fprintf(stderr, "16_deferred: %u light%s, path %s, view %s\n", light_count_,
                     light_count_ == 1 ? "" : "s", forward_path_ ? "forward" : "deferred",
                     view.c_str());
        create_frame_data(context.frames_in_flight,
                          context.properties.limits.maxStorageBufferRange);
        resize(context.extent);
    }

    // The G-buffer and the forward path's depth are as large as the target;
    // the lighting pass's set 1 then points at the new images.
    void resize(VkExtent2D extent) override {
        gbuffer_.resize(extent);
        lighting_.resize(gbuffer_);
        forward_.resize(extent);
    }

    void record(const vkt::Frame& frame) override {
        update(frame.slot, frame.extent, float(frame.time));
        last_ = {frame.slot, frame.extent};  // what verify() checks
        const VkCommandBuffer cmd = frame.cmd;
        const VkDescriptorSet frame_set = frame_sets_[frame.slot];
        if (forward_path_) {
            auto scope = frame.gpu_scope("forward");
            forward_.record(cmd, frame_set, frame.extent, frame.target_view, objects_);
            return;
        }
        // [deferred-frame]
        {
            auto scope = frame.gpu_scope("gbuffer");
            gbuffer_.to_write(cmd);
            gbuffer_.draw(cmd, frame_set, frame.extent, objects_);
            gbuffer_.to_read(cmd);
        }
        auto scope = frame.gpu_scope("lighting");
        lighting_.draw(cmd, frame_set, frame.extent, frame.target_view,
                       {view_, 0, light_count_, 1.0f});
        // [/deferred-frame]
    }

private:
    // Set 0, one per frame in flight: the frame's uniforms and its lights.
    // (Set 1, the G-buffer, is the lighting pass's.)
    static vkt::DescriptorSetLayout create_frame_layout(VkDevice device) {
        const VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, both, nullptr},
            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        };
        return vkt::create_descriptor_set_layout(device, bindings);
    }

    // Chapter 07's per-frame buffers and sets, with chapter 07's helpers:
    // only the storage buffer of lights is new here.
    void create_frame_data(uint32_t slots, uint32_t max_storage_range) {
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, slots},
                                              {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, slots}};
        pool_ = vkt::create_descriptor_pool(device_, slots, sizes);
        // --verify also needs a copy of the lights moved out of reach (see verify).
        const VkDeviceSize lights_size =
            VkDeviceSize{light_count_} * sizeof(vkt::PointLight) * (verify_.empty() ? 1 : 2);
        if (lights_size > max_storage_range)
            throw vkt::Error("--lights " + std::to_string(light_count_) +
                             ": more than this device's maxStorageBufferRange allows");
        for (uint32_t i = 0; i < slots; ++i) {
            uniforms_.push_back(vkt::create_host_buffer(gpu_, sizeof(FrameUniforms),
                                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            lights_.push_back(
                vkt::create_host_buffer(gpu_, lights_size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT));
            frame_sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, frame_layout_));
            vkt::write_buffer_descriptor(device_, frame_sets_[i], 0,
                                         VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniforms_[i].buffer, 0,
                                         sizeof(FrameUniforms));
            vkt::write_buffer_descriptor(device_, frame_sets_[i], 1,
                                         VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, lights_[i].buffer, 0,
                                         VK_WHOLE_SIZE);
        }
    }

    // [update]
    void update(uint32_t slot, VkExtent2D extent, float t) {
        uniforms_now_ = frame_uniforms(float(extent.width) / float(extent.height), light_count_);
        std::memcpy(uniforms_[slot].mapped, &uniforms_now_, sizeof uniforms_now_);
        lights_now_ = make_lights(light_count_, t);
        std::memcpy(lights_[slot].mapped, lights_now_.data(),
                    lights_now_.size() * sizeof(vkt::PointLight));
        objects_ = make_objects(t);
    }
    // [/update]

    // [verify]
    // --verify: the checks of deferred_verify.hpp, on the last frame's scene,
    // once the runner's loop is over and the GPU idle. Lights n .. 2n - 1 of
    // that frame's buffer become the n lights lifted far out of reach.
    void verify() override {
        if (verify_.empty()) return;
        const uint32_t n = light_count_;
        const VkDescriptorSet set = frame_sets_[last_.slot];
        std::vector<vkt::PointLight> lifted = lights_now_;
        for (vkt::PointLight& light : lifted) light.position.y += 1000.0f;
        std::memcpy(static_cast<vkt::PointLight*>(lights_[last_.slot].mapped) + n, lifted.data(),
                    n * sizeof(vkt::PointLight));
        const VkExtent2D e = last_.extent;
        const GBuffer& g = gbuffer_.images();
        vkt::deferred::verify(
            verify_,
            {gpu_,
             e,
             {g.base_colour.image, g.normal.image, g.material.image, g.depth.image},
             uniforms_now_.inverse_view_proj,
             eye,
             uniforms_now_.ambient,
             lights_now_},
            {[&](VkCommandBuffer cmd) { gbuffer_.record(cmd, set, e, objects_); },
             [&](VkCommandBuffer cmd, VkImageView target, const LightingPush& push) {
                 lighting_.draw(cmd, set, e, target, push, true);
             },
             [&](VkCommandBuffer cmd, VkImageView target) {
                 forward_.record(cmd, set, e, target, objects_, true);
             }});
    }
    // [/verify]

    vkt::Gpu gpu_;
    VkDevice device_;
    bool forward_path_;
    uint32_t light_count_;
    std::string verify_;  // the check, or empty
    struct {
        uint32_t slot = 0;
        VkExtent2D extent{};
    } last_;  // the last frame recorded
    int32_t view_ = view_lit;
    // Declared in the order they are made: each part needs those above it.
    vkt::DescriptorSetLayout frame_layout_;
    SceneMeshes scene_;
    GBufferPass gbuffer_;
    ch16::LightingPass lighting_;
    ch16::ForwardPass forward_;
    vkt::DescriptorPool pool_;
    std::vector<vkt::Buffer> uniforms_, lights_;  // [slot]
    std::vector<VkDescriptorSet> frame_sets_;     // [slot]
    FrameUniforms uniforms_now_{};                // this frame's, for --verify
    std::vector<vkt::PointLight> lights_now_;     // this frame's
    std::vector<Object> objects_;                 // this frame's
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "16_deferred", .title = "16 - deferred"};
    // DEPTH_ATTACHMENT_OPTIMAL and DEPTH_READ_ONLY_OPTIMAL (chapter 08).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        {.name = "--path",
         .type = vkt::OptionType::choice,
         .value_name = "PATH",
         .help = "deferred (G-buffer, then a lighting pass) or forward (lit as drawn)",
         .default_value = "deferred",
         .choices = {"deferred", "forward"}},
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "lit, or one G-buffer target alone: albedo, normal, material, depth",
         .default_value = "lit",
         .choices = {std::begin(views), std::end(views)}},
        {.name = "--lights",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many point lights, 1 to 65536 (2 MiB of lights per frame in flight)",
         .default_value = "32",
         .min = 1,
         .max = double(max_lights)},
        {.name = "--verify",
         .type = vkt::OptionType::choice,
         .value_name = "CHECK",
         .help = "check the last frame: cpu (against the CPU reference), additivity, forward",
         .choices = {"cpu", "additivity", "forward"}},
    };
    spec.check_options = check_flags;
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Deferred>(context);
    });
}
