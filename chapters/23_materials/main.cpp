// Chapter 23: physically based materials and HDR.
//
// A surface is described the way glTF describes it: a base colour, how
// metallic it is and how rough, and optionally a normal map, an occlusion
// map and an emissive colour, each a texture or a factor. The light it sends
// to the eye is the light arriving from every direction weighed by its BRDF,
// here Cook-Torrance's microfacet model (GGX, Smith, Schlick). The result is
// radiance, a number that may well be 20 where a highlight is: it goes into
// a floating-point (HDR) image, and a second pass turns it into a picture,
// scaled by the exposure and squeezed into 0..1 by a tone curve (ACES).

#include "blocks.hpp"
#include "bloom_view.hpp"
#include "environment.hpp"
#include "flags.hpp"
#include "grid.hpp"
#include "ibl_view.hpp"
#include "materials.hpp"
#include "verify.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/bloom.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace {

// [hdr-format]
// Radiance is stored as 16-bit floats: up to 65504, with about three
// significant digits at every size, where an _SRGB target stops at 1.0.
constexpr VkFormat hdr_format = VK_FORMAT_R16G16B16A16_SFLOAT;
// [/hdr-format]

class Materials : public vkt::Renderer {
public:
    explicit Materials(const vkt::Context& context)
        : gpu_(context.gpu()),
          furnace_(context.options.text("--scene") == "furnace"),
          spheres_(grid::spheres(furnace_)),
          model_(context.options.has("--model")),
          ibl_(context.options.text("--sky") == "environment"),
          verify_(context.options.has("--verify") ? context.options.text("--verify") : ""),
          exposure_(float(context.options.number("--exposure"))),
          tone_map_(context.options.text("--tone-map") == "aces" ? 0 : 1),
          bloom_strength_(float(context.options.number("--bloom"))),
          bloom_(gpu_, context.chapter, 1, context.options.text("--bloom-average") == "karis") {
        // [load]
        // A glTF file with every texture of the metallic-roughness model, or
        // the generated spheres, whose materials are the grid's numbers.
        if (model_) {
            const std::string path = context.options.text("--model");
            scene_ = vkt::load_gltf(path, uint64_t(context.options.integer("--max-memory")),
                                    vkt::GltfMaterials::metallic_roughness);
            for (const std::string& warning : scene_.warnings)
                std::fprintf(stderr, "23_materials: %s: warning: %s\n",
                             vkt::shown_path(path).c_str(), warning.c_str());
        } else {
            scene_ = grid::sphere_scene(furnace_);
        }
        // [/load]
        materials_.emplace(gpu_, scene_.materials, scene_.images);
        // [make-environment]
        // --sky environment: the sky and the split sum's three images, made
        // before the first frame (environment.hpp); the sun is the key light's.
        if (ibl_)
            environment_.emplace(gpu_, context.chapter, grid::lights(false)[0].direction, furnace_);
        // [/make-environment]
        vertices_ = vkt::create_device_buffer(gpu_, scene_.vertices.data(),
                                              scene_.vertices.size() * sizeof(vkt::GltfVertex),
                                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        indices_ = vkt::create_device_buffer(gpu_, scene_.indices.data(),
                                             scene_.indices.size() * sizeof(uint32_t),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        // The frame's block (set 0): camera, lights, sky. One buffer for every frame
        // in flight: it changes only at a resize or from the overlay, GPU idle.
        frame_buffer_ =
            vkt::create_host_buffer(gpu_, sizeof(FrameBlock), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        const VkDescriptorSetLayoutBinding frame_binding{
            0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
            VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
        frame_layout_ = vkt::create_descriptor_set_layout(gpu_.device, {&frame_binding, 1});
        // The tone-mapping pass's inputs: the HDR image, and the bloom.
        const VkDescriptorSetLayoutBinding hdr_bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr},
            {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT,
             nullptr}};
        hdr_layout_ = vkt::create_descriptor_set_layout(gpu_.device, hdr_bindings);
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                              {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2}};
        pool_ = vkt::create_descriptor_pool(gpu_.device, 2, sizes);
        frame_set_ = vkt::allocate_descriptor_set(gpu_.device, pool_, frame_layout_);
        hdr_set_ = vkt::allocate_descriptor_set(gpu_.device, pool_, hdr_layout_);
        vkt::write_buffer_descriptor(gpu_.device, frame_set_, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                     frame_buffer_.buffer, 0, sizeof(FrameBlock));
        hdr_sampler_ = vkt::create_sampler(gpu_.device, 0.0f);  // read by texelFetch only

        const VkVertexInputBindingDescription binding{0, sizeof(vkt::GltfVertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::GltfVertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::GltfVertex, normal)},
            {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(vkt::GltfVertex, uv)},
            {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(vkt::GltfVertex, tangent)},
        };
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                       sizeof(DrawPush)};
        // Set 2, under the environment: its sky and the split sum's images.
        const VkDescriptorSetLayout scene_sets[] = {frame_layout_, materials_->layout(),
                                                    ibl_ ? environment_->layout() : VK_NULL_HANDLE};
        scene_layout_ = vkt::create_pipeline_layout(
            gpu_.device, std::span(scene_sets, ibl_ ? 3 : 2), {&push, 1});
        const vkt::ShaderModule vertex =
            vkt::load_shader(gpu_.device, context.chapter, "scene.vert");
        const vkt::ShaderModule fragment =
            vkt::load_shader(gpu_.device, context.chapter, ibl_ ? "scene_ibl.frag" : "scene.frag");
        depth_format_ = vkt::choose_depth_format(gpu_.physical);
        // [scene-pipeline]
        // The scene pass draws into the HDR image: its colour format is
        // hdr_format, not the _SRGB target's.
        scene_pipeline_ = vkt::create_graphics_pipeline(
            gpu_.device, {.vertex = vertex,
                          .fragment = fragment,
                          .layout = scene_layout_,
                          .bindings = {&binding, 1},
                          .attributes = attributes,
                          .cull_mode = model_ ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT,
                          .color_formats = {hdr_format},
                          .depth_format = depth_format_,
                          .fragment_specialization = TermConstant(context.options).info()});
        // [/scene-pipeline]
        const vkt::ShaderModule fullscreen =
            vkt::load_shader(gpu_.device, context.chapter, "fullscreen.vert");
        if (ibl_)
            environment_->make_background(
                scene_layout_, fullscreen,
                vkt::load_shader(gpu_.device, context.chapter, "background.frag"), hdr_format,
                depth_format_);
        const std::string& view = context.options.text("--view");
        if (view == "bloom")  // the bloom's levels, drawn once the bloom is made (page 23d)
            bloom_view_.emplace(gpu_, context.chapter, bloom_, fullscreen, hdr_format);
        else if (view != "scene")  // the light's images, not the scene
            view_.emplace(gpu_, context.chapter, *environment_, IblView::kind(view), fullscreen,
                          hdr_format, depth_format_);

        // [tonemap-pipeline]
        // The second pass: one full-screen triangle into the _SRGB target,
        // the exposure and the curve's choice as push constants.
        const VkPushConstantRange tonemap_push{VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                               sizeof(TonemapPush)};
        const VkDescriptorSetLayout tonemap_sets[] = {hdr_layout_};
        tonemap_layout_ =
            vkt::create_pipeline_layout(gpu_.device, tonemap_sets, {&tonemap_push, 1});
        const vkt::ShaderModule tonemap =
            vkt::load_shader(gpu_.device, context.chapter, "tonemap.frag");
        tonemap_pipeline_ =
            vkt::create_graphics_pipeline(gpu_.device, {.vertex = fullscreen,
                                                        .fragment = tonemap,
                                                        .layout = tonemap_layout_,
                                                        .color_formats = {context.color_format}});
        // [/tonemap-pipeline]

        // [check-format]
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(gpu_.physical, hdr_format, &properties);
        const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT |
                                            VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                            VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT;  // the bloom's
        if ((properties.optimalTilingFeatures & needed) != needed)
            throw vkt::Error(
                "VK_FORMAT_R16G16B16A16_SFLOAT cannot be drawn into, sampled and stored to here");
        // [/check-format]
        resize(context.extent);
        print_settings(context.options);
    }

    // [overlay]
    // In a window (chapter 21's overlay): the exposure, the curve and the
    // bloom are push constants, read by the next frame as they are; the sky is in the frame's
    // uniform block, which waits for the GPU before it is rewritten.
    void overlay(vkt::OverlayPanel& panel) override {
        panel.slider("Exposure (EV)", exposure_, -6.0f, 6.0f);
        const char* const curves[] = {"ACES", "clamp"};
        int curve = int(tone_map_);
        if (panel.choice("Tone map", curve, curves)) tone_map_ = uint32_t(curve);
        panel.slider("Bloom", bloom_strength_, 0.0f, 1.0f);
        if (panel.slider("Sky", sky_scale_, 0.0f, 4.0f)) {
            VKT_CHECK(vkDeviceWaitIdle(gpu_.device));
            write_frame_block();
        }
    }
    // [/overlay]

    // The HDR image and depth follow the target's size; the GPU is idle.
    void resize(VkExtent2D extent) override {
        extent_ = extent;
        // [hdr-image]
        // Drawn into by the scene pass, sampled by the tone-mapping pass, and
        // copied out by --verify.
        hdr_ =
            vkt::create_image_2d(gpu_.physical, gpu_.device, hdr_format, extent,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                     VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_IMAGE_ASPECT_COLOR_BIT);
        // [/hdr-image]
        vkt::write_image_descriptor(gpu_.device, hdr_set_, 0, hdr_.view, hdr_sampler_,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        depth_ = vkt::create_depth_image(gpu_.physical, gpu_.device, depth_format_, extent);
        bloom_.resize(extent, hdr_.view);
        if (bloom_view_) bloom_view_->resize();
        vkt::write_image_descriptor(gpu_.device, hdr_set_, 1, bloom_.level0(), bloom_.sampler(),
                                    VK_IMAGE_LAYOUT_GENERAL);
        write_frame_block();
    }

    void record(const vkt::Frame& frame) override {
        const VkCommandBuffer cmd = frame.cmd;
        // [scene-pass]
        // The HDR image is redrawn each frame: after the last frame's
        // tone-mapping pass (and bloom) have read it, its contents are thrown away.
        vkt::image_barrier(
            cmd, hdr_.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        vkt::begin_depth_frame(cmd, depth_.image);
        const glm::vec3 sky = sky_scale_ * grid::sky(furnace_);
        {
            auto scope = frame.gpu_scope("scene");
            vkt::begin_rendering(cmd, hdr_.view, frame.extent, {{sky.r, sky.g, sky.b, 1.0f}},
                                 depth_.view);
            // [/scene-pass]
            vkt::set_viewport_and_scissor(cmd, frame.extent);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_layout_, 0, 1,
                                    &frame_set_, 0, nullptr);
            if (view_) view_->draw(cmd, frame.extent);
            if (ibl_ && !view_) environment_->draw_background(cmd, scene_layout_);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_pipeline_);
            const VkBuffer buffer = vertices_.buffer;
            const VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
            vkCmdBindIndexBuffer(cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
            // [material-bind]
            for (size_t d = 0; d < (view_ ? 0 : scene_.draws.size()); ++d) {
                const vkt::GltfDraw& draw = scene_.draws[d];
                const vkt::GltfPrimitive& primitive = scene_.primitives[draw.primitive];
                const uint32_t material = model_ ? primitive.material : 0;
                const VkDescriptorSet set = materials_->set(material);
                vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_layout_, 1, 1,
                                        &set, 0, nullptr);
                // A glTF draw pushes its material's factors; a sphere its grid's.
                const vkt::pbr::Material& m = spheres_[model_ ? 0 : d].material;
                const DrawPush push =
                    model_
                        ? materials_->push(material, draw.world)
                        : DrawPush{draw.world, glm::vec4(m.base_colour, 1.0f),
                                   glm::vec4(m.metallic, m.roughness, 1.0f, 1.0f), glm::vec4(0.0f)};
                vkCmdPushConstants(cmd, scene_layout_,
                                   VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                   sizeof push, &push);
                vkCmdDrawIndexed(cmd, primitive.index_count, 1, primitive.first_index, 0, 0);
            }
            // [/material-bind]
            vkCmdEndRendering(cmd);
        }

        // [tonemap-barrier]
        // Colour writes to shader reads: the tone-mapping pass (and the
        // bloom's first compute pass) sample every pixel the scene pass wrote.
        vkt::image_barrier(
            cmd, hdr_.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        // [/tonemap-barrier]
        if (bloom_strength_ > 0.0f || bloom_view_) {
            auto bloom_scope = frame.gpu_scope("bloom");
            bloom_.record(cmd, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                          bloom_view_ ? bloom_view_->halfway() : nullptr);
        }
        if (bloom_view_) bloom_view_->draw(cmd, hdr_, frame.extent);  // over the scene, unmixed
        // [tonemap-draw]
        auto scope = frame.gpu_scope("tone map");
        vkt::begin_colour_rendering(cmd, frame.target_view, frame.extent,
                                    VK_ATTACHMENT_LOAD_OP_DONT_CARE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tonemap_pipeline_);
        vkt::set_viewport_and_scissor(cmd, frame.extent);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, tonemap_layout_, 0, 1,
                                &hdr_set_, 0, nullptr);
        const TonemapPush settings{std::exp2(exposure_), tone_map_,
                                   bloom_view_ ? 0.0f : bloom_strength_, float(bloom_.levels())};
        vkCmdPushConstants(cmd, tonemap_layout_, VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof settings,
                           &settings);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
        // [/tonemap-draw]
    }

    // --verify: the last frame's HDR image against the CPU reference.
    void verify() override {
        if (verify_ == "lut")
            verify::check_lut(gpu_, *environment_);
        else if (!verify_.empty())
            verify::check(verify_, verify::read_hdr(gpu_, hdr_.image, extent_), extent_, furnace_);
    }

private:
    // The camera frames the spheres, or the model's bounds; the lights and
    // the sky are the grid's (grid.hpp).
    void write_frame_block() {
        const float aspect = float(extent_.width) / float(extent_.height);
        FrameBlock block{};
        const grid::Camera camera =
            model_ ? grid::frame_model(scene_, aspect) : grid::camera(aspect);
        block.clip_from_world = camera.clip_from_world;
        block.eye = glm::vec4(camera.eye, 1.0f);
        const auto lights = grid::lights(furnace_);
        for (int i = 0; i < 2; ++i) {
            block.light_direction[i] = glm::vec4(lights[size_t(i)].direction, 0.0f);
            block.light_radiance[i] = glm::vec4(lights[size_t(i)].radiance, 0.0f);
        }
        block.world_from_clip = glm::inverse(block.clip_from_world);
        block.viewport = glm::vec4(float(extent_.width), float(extent_.height), 0.0f, 0.0f);
        // The uniform sky and its samples, or the environment's strength.
        block.sky = ibl_ ? glm::vec4(glm::vec3(sky_scale_), 0.0f)
                         : glm::vec4(sky_scale_ * grid::sky(furnace_), float(grid::sky_samples));
        std::memcpy(frame_buffer_.mapped, &block, sizeof block);
    }

    vkt::Gpu gpu_;
    bool furnace_;
    std::vector<grid::Sphere> spheres_;  // the grid's materials (or the furnace's one)
    bool model_;
    bool ibl_;            // --sky environment
    std::string verify_;  // the check, or empty
    float exposure_;      // in stops (EV): the tone-mapping pass multiplies by 2^exposure_
    uint32_t tone_map_;   // 0: ACES, 1: clamp
    float sky_scale_ = 1.0f;
    float bloom_strength_;  // 0: no bloom
    vkt::Bloom bloom_;
    VkExtent2D extent_{};
    vkt::GltfScene scene_;
    std::optional<MaterialSets> materials_;
    std::optional<Environment> environment_;
    std::optional<IblView> view_;          // --view sky, irradiance, prefiltered or brdf
    std::optional<BloomView> bloom_view_;  // --view bloom
    vkt::Buffer vertices_, indices_, frame_buffer_;
    vkt::DescriptorSetLayout frame_layout_, hdr_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet frame_set_ = VK_NULL_HANDLE, hdr_set_ = VK_NULL_HANDLE;
    vkt::Sampler hdr_sampler_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image hdr_, depth_;
    vkt::PipelineLayout scene_layout_, tonemap_layout_;
    vkt::Pipeline scene_pipeline_, tonemap_pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "23_materials",
                          .title = "23 - Physically based materials and HDR"};
    spec.overlay = true;  // in a window: the exposure, the tone curve, the bloom and the sky, live
    // maintenance4, as chapter 13: glslang writes the bloom's workgroup size
    // as LocalSizeId, which needs it (every Vulkan 1.3 device has it).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts),
                                  VKT_FEATURE_13(maintenance4)};
    spec.options = {
        {.name = "--exposure",
         .type = vkt::OptionType::number,
         .value_name = "EV",
         .help =
             "exposure in stops: radiance is multiplied by 2^EV before the tone curve (-10..10)",
         .default_value = "0",
         .min = -10,
         .max = 10},
        {.name = "--tone-map",
         .type = vkt::OptionType::choice,
         .value_name = "CURVE",
         .help = "aces: Narkowicz's fit of the ACES filmic curve; clamp: cut at 1",
         .default_value = "aces",
         .choices = {"aces", "clamp"}},
        {.name = "--scene",
         .type = vkt::OptionType::choice,
         .value_name = "SCENE",
         .help = "grid: spheres, metallic x roughness; furnace: a white sphere under a white sky",
         .default_value = "grid",
         .choices = {"grid", "furnace"}},
        {.name = "--sky",
         .type = vkt::OptionType::choice,
         .value_name = "SKY",
         .help = "uniform: one radiance from everywhere, sampled per pixel; environment: a "
                 "generated HDR sky, image-based light (split sum)",
         .default_value = "uniform",
         .choices = {"uniform", "environment"}},
        {.name = "--bloom",
         .type = vkt::OptionType::number,
         .value_name = "F",
         .help = "how much bloom (a blur in compute, mip by mip) is mixed in: 0 (off) to 1",
         .default_value = "0",
         .min = 0,
         .max = 1},
        bloom_average_option(),
        term_option(),
        {.name = "--model",
         .type = vkt::OptionType::text,
         .value_name = "FILE",
         .help = "draw a glTF 2.0 file (.gltf or .glb) with its metallic-roughness textures"},
        vkt::max_memory_option(),
        {.name = "--view",
         .type = vkt::OptionType::choice,
         .value_name = "VIEW",
         .help = "scene; or in its place the image-based light's images: sky, irradiance, "
                 "prefiltered (its six levels), brdf (the table); or bloom (the bloom's levels)",
         .default_value = "scene",
         .choices = {"scene", "sky", "irradiance", "prefiltered", "brdf", "bloom"}},
        {.name = "--verify",
         .type = vkt::OptionType::choice,
         .value_name = "CHECK",
         .help = "check the last frame: cpu (against the CPU reference), furnace; or lut (the "
                 "BRDF table against the CPU's)",
         .choices = {"cpu", "furnace", "lut"}},
    };
    spec.check_options = check_flags;
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Materials>(context);
    });
}
