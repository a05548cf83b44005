// Chapter 21: multisampling.
//
// A pixel that a triangle's edge crosses is either in or out when the
// rasteriser looks at one point per pixel: thin, bright geometry breaks into
// stair steps and gaps. With multisampling (MSAA) the rasteriser tests
// several sample points per pixel, depth is tested per sample, and the
// fragment shader still runs once per pixel, its colour written to every
// sample the triangle covers. At the end of rendering the samples of each
// pixel are averaged (resolved) into the single-sample image the runner
// shows. This file draws a wheel of thin spokes and two quads that cut
// through each other into a multisampled colour and depth target of its own,
// and resolves it into the frame's target with dynamic rendering.

#include "sample_counts.hpp"

#include "vkt/core/barrier.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Vertex {
    glm::vec3 position;  // world units; z is depth (0 near, 1 far)
    glm::vec3 colour;
    float striped;  // 1 on the quad whose fragment shader draws stripes
};

struct Scene {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    uint32_t wheel_indices = 0;  // the wheel first (turned each frame), then the quads
};

void add_quad(Scene& scene, const glm::vec3 (&corners)[4], glm::vec3 colour, float striped) {
    const auto first = uint32_t(scene.vertices.size());
    for (const glm::vec3& corner : corners) scene.vertices.push_back({corner, colour, striped});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + i);
}

// [scene]
// Everything an aliased picture gets wrong: twelve spokes two pixels wide
// (at 240 pixels high) around the origin, turning, so their edges are never
// along a row or column; two quads that cut through each other, so one edge
// is made by the depth test alone; stripes on one quad 1.25 pixels wide,
// close to the pixel spacing, an edge inside a triangle that only sample
// shading sees.
Scene build_scene() {
    Scene scene;
    const glm::vec3 spoke_colour(1.0f, 0.92f, 0.7f);
    for (int s = 0; s < 12; ++s) {
        const float a = 2.0f * 3.14159265f * float(s) / 12.0f;
        const glm::vec2 along(std::cos(a), std::sin(a)), across(-along.y, along.x);
        const glm::vec2 inner = 0.06f * along, outer = 0.78f * along, half = 0.009f * across;
        add_quad(scene,
                 {{inner - half, 0.5f},
                  {outer - half, 0.5f},
                  {outer + half, 0.5f},
                  {inner + half, 0.5f}},
                 spoke_colour, 0.0f);
    }
    scene.wheel_indices = uint32_t(scene.indices.size());
    // An orange quad leaning back to the right, a teal striped one leaning
    // back to the left and turned by 25 degrees: they meet where the depths
    // are equal, along a slanted line.
    add_quad(scene,
             {{0.2f, -0.75f, 0.3f}, {1.2f, -0.75f, 0.7f}, {1.2f, 0.75f, 0.7f}, {0.2f, 0.75f, 0.3f}},
             {1.0f, 0.45f, 0.1f}, 0.0f);
    const float c = std::cos(0.436f), s = std::sin(0.436f);
    glm::vec3 teal[4];
    const glm::vec2 local[4] = {{-0.55f, -0.45f}, {0.55f, -0.45f}, {0.55f, 0.45f}, {-0.55f, 0.45f}};
    for (int i = 0; i < 4; ++i)
        teal[i] = {0.7f + c * local[i].x - s * local[i].y, s * local[i].x + c * local[i].y,
                   0.5f - 0.36f * local[i].x};
    add_quad(scene, teal, {0.1f, 0.75f, 0.8f}, 1.0f);
    return scene;
}
// [/scene]

// World to clip space: the view spans y from -1 to 1 (up), x as far as the
// aspect ratio allows (at least -4/3 to 4/3), depth as given; Vulkan's y is down.
glm::mat4 clip_from_world(VkExtent2D extent, glm::vec2 centre, float angle) {
    const float aspect = float(extent.width) / float(extent.height);
    const float scale_y = aspect >= 4.0f / 3.0f ? 1.0f : aspect * 0.75f;
    const float sx = scale_y / aspect, sy = -scale_y, c = std::cos(angle), s = std::sin(angle);
    glm::mat4 m(1.0f);  // column-major: m[column][row]
    m[0] = {sx * c, sy * s, 0, 0};
    m[1] = {-sx * s, sy * c, 0, 0};
    m[3] = {sx * centre.x, sy * centre.y, 0, 1};
    return m;
}

class Multisampling : public vkt::Renderer {
public:
    explicit Multisampling(const vkt::Context& context)
        : physical_(context.physical), device_(context.device), format_(context.color_format) {
        const vkt::Options& options = context.options;
        // [samples]
        // --samples against what this device can render: a count it does
        // not offer is refused by name, before anything is made.
        const VkSampleCountFlags offered = offered_sample_counts(context.properties.limits);
        samples_ = checked_sample_count(uint32_t(std::stoul(options.text("--samples"))), offered,
                                        context.properties.deviceName);
        // [/samples]
        shading_ =
            options.has("--sample-shading") ? float(options.number("--sample-shading")) : 0.0f;
        can_shade_ = context.features.has(VKT_FEATURE_10(sampleRateShading));
        if (shading_ > 0.0f && !can_shade_)
            throw vkt::Error(std::string("--sample-shading: ") + context.properties.deviceName +
                             " " +
                             vkt::lacks_feature("sampleRateShading", {},
                                                context.hidden.hides("sampleRateShading")));
        for (uint32_t count = 1; count <= 64; count *= 2)  // the overlay's choices
            if (offered & count) {
                offered_.push_back(VkSampleCountFlagBits(count));
                offered_names_.push_back(std::to_string(count));
            }

        const Scene scene = build_scene();
        wheel_indices_ = scene.wheel_indices;
        index_count_ = uint32_t(scene.indices.size());
        const vkt::Gpu gpu = context.gpu();
        vertices_ = vkt::create_device_buffer(gpu, scene.vertices.data(),
                                              scene.vertices.size() * sizeof(Vertex),
                                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        indices_ = vkt::create_device_buffer(gpu, scene.indices.data(),
                                             scene.indices.size() * sizeof(uint32_t),
                                             VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        depth_format_ = vkt::choose_depth_format(physical_);
        extent_ = context.extent;
        create_targets(extent_);
        vertex_ = vkt::load_shader(device_, context.chapter, "scene.vert");
        fragment_ = vkt::load_shader(device_, context.chapter, "scene.frag");
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        layout_ = vkt::create_pipeline_layout(device_, {}, {&push, 1});
        create_pipeline();
        std::fprintf(stderr, "21_multisampling: %ux samples (the device offers %s), %s; %s\n",
                     unsigned(samples_), sample_count_list(offered).c_str(),
                     shading_ > 0.0f ? "sample shading on" : "sample shading off",
                     memory_note().c_str());
    }

    void resize(VkExtent2D extent) override {
        extent_ = extent;
        create_targets(extent);
    }

    // [overlay]
    // In a window, the overlay (vkt/frame/overlay.hpp) changes the sample
    // count and sample shading live. Both are baked into the pipeline, and
    // the count into the images too: one multisampled image serves every
    // frame in flight, so a change waits for the GPU to finish them all
    // before it makes both again.
    void overlay(vkt::OverlayPanel& panel) override {
        int chosen = int(std::find(offered_.begin(), offered_.end(), samples_) - offered_.begin());
        std::vector<const char*> labels;
        labels.reserve(offered_names_.size());
        for (const std::string& name : offered_names_) labels.push_back(name.c_str());
        bool changed = panel.choice("Samples", chosen, labels);
        bool shading = shading_ > 0.0f;
        if (can_shade_) changed = panel.checkbox("Sample shading", shading) || changed;
        panel.text(memory_note());
        if (!changed) return;
        VKT_CHECK(vkDeviceWaitIdle(device_));
        samples_ = offered_[size_t(chosen)];
        shading_ = shading ? 1.0f : 0.0f;
        create_targets(extent_);
        create_pipeline();
    }
    // [/overlay]

    void record(const vkt::Frame& frame) override {
        const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;
        // [barriers]
        // One multisampled image serves every frame in flight, like the depth
        // image: its old samples are thrown away (UNDEFINED), after the last
        // frame's writes and resolve reads (both COLOR_ATTACHMENT_OUTPUT).
        vkt::begin_depth_frame(frame.cmd, depth_.image);
        if (msaa)
            vkt::image_barrier(
                frame.cmd, colour_.image, VK_IMAGE_LAYOUT_UNDEFINED,
                VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        // [/barriers]
        // --benchmark's GPU time of the draws and the resolve, to the end of record().
        auto scope = frame.gpu_scope("render");

        // [rendering]
        // With MSAA the samples go into our own image, and rendering ends by
        // averaging each pixel's samples into the frame's target (resolveMode
        // AVERAGE, resolveImageView). The samples themselves are not stored:
        // once resolved nobody reads them, which is what lets a tiling GPU
        // keep them on chip. At 1x the frame's target is drawn into directly.
        const VkRenderingAttachmentInfo colour{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = msaa ? VkImageView(colour_.view) : frame.target_view,
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .resolveMode = msaa ? VK_RESOLVE_MODE_AVERAGE_BIT : VK_RESOLVE_MODE_NONE,
            .resolveImageView = msaa ? frame.target_view : VK_NULL_HANDLE,
            .resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.02f, 0.02f, 0.04f, 1.0f}}},
        };
        // Depth has as many samples as colour (a rule of the API): each
        // sample keeps its own depth, so where two surfaces cut through each
        // other the edge is smoothed as well.
        const VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = depth_.view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .resolveMode = VK_RESOLVE_MODE_NONE,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
            .clearValue = {.depthStencil = {1.0f, 0}},
        };
        const VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .renderArea = {{0, 0}, frame.extent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &colour,
            .pDepthAttachment = &depth,
        };
        vkCmdBeginRendering(frame.cmd, &rendering);
        // [/rendering]

        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        const VkBuffer vertex_buffer = vertices_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(frame.cmd, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
        // The wheel turns 0.3 rad a second from a start that leaves no spoke
        // along a row or a column; the quads stay put.
        const glm::mat4 wheel =
            clip_from_world(frame.extent, {-0.62f, 0.02f}, 0.13f + 0.3f * float(frame.time));
        const glm::mat4 still = clip_from_world(frame.extent, {0.0f, 0.0f}, 0.0f);
        vkCmdPushConstants(frame.cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof wheel, &wheel);
        vkCmdDrawIndexed(frame.cmd, wheel_indices_, 1, 0, 0, 0);
        vkCmdPushConstants(frame.cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof still, &still);
        vkCmdDrawIndexed(frame.cmd, index_count_ - wheel_indices_, 1, wheel_indices_, 0, 0);
        vkCmdEndRendering(frame.cmd);
    }

private:
    void create_pipeline() {
        const VkVertexInputBindingDescription binding{0, sizeof(Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, colour)},
            {2, 0, VK_FORMAT_R32_SFLOAT, offsetof(Vertex, striped)},
        };
        // [pipeline]
        // The pipeline must be made for the sample count of the attachments
        // it draws into; sample shading is a pipeline setting too.
        pipeline_ = vkt::create_graphics_pipeline(device_, {
                                                               .vertex = vertex_,
                                                               .fragment = fragment_,
                                                               .layout = layout_,
                                                               .bindings = {&binding, 1},
                                                               .attributes = attributes,
                                                               .color_formats = {format_},
                                                               .depth_format = depth_format_,
                                                               .samples = samples_,
                                                               .min_sample_shading = shading_,
                                                           });
        // [/pipeline]
    }

    // [targets]
    // The multisampled colour and depth images, of the target's size. Both
    // are transient: their contents never outlive one rendering (colour is
    // resolved, depth thrown away), so where the device has lazily allocated
    // memory they take it, and a tiling GPU may never back them with memory
    // at all. At 1x only depth is ours, as in chapter 08.
    void create_targets(VkExtent2D extent) {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent, samples_,
                                         samples_ != VK_SAMPLE_COUNT_1_BIT);
        colour_ = samples_ == VK_SAMPLE_COUNT_1_BIT
                      ? vkt::Image{}
                      : vkt::create_attachment_image(physical_, device_, format_, extent,
                                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                                     VK_IMAGE_ASPECT_COLOR_BIT, samples_, true);
    }
    // [/targets]

    // What the samples cost: the memory the two images asked for, and
    // whether it is lazily allocated (then only what is touched, if any).
    std::string memory_note() const {
        const double mib = double(colour_.bytes + depth_.bytes) / (1024.0 * 1024.0);
        char line[200];
        if (samples_ == VK_SAMPLE_COUNT_1_BIT)
            std::snprintf(line, sizeof line, "depth %.2f MiB", mib);
        else
            std::snprintf(line, sizeof line,
                          "multisampled colour and depth %.2f MiB, transient, %s", mib,
                          colour_.lazily_allocated && depth_.lazily_allocated
                              ? "lazily allocated"
                              : "not lazily allocated (the device has no such memory)");
        return line;
    }

    VkPhysicalDevice physical_;
    VkDevice device_;
    VkFormat format_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
    std::vector<VkSampleCountFlagBits> offered_;  // what this device can render, 1 first
    std::vector<std::string> offered_names_;      // the same, as the overlay names them
    float shading_ = 0.0f;                        // minSampleShading; 0: off
    bool can_shade_ = false;                      // the sampleRateShading feature
    VkExtent2D extent_{};
    vkt::ShaderModule vertex_, fragment_;  // kept: the overlay makes the pipeline again
    vkt::Buffer vertices_;
    vkt::Buffer indices_;
    uint32_t wheel_indices_ = 0, index_count_ = 0;
    vkt::Image colour_;  // multisampled; empty at 1x
    vkt::Image depth_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "21_multisampling", .title = "21 - Multisampling"};
    spec.overlay = true;  // in a window: the sample count and sample shading, live
    // Chapter 08's depth layouts; sample shading only where --sample-shading asks.
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.requirements.optional_features = {VKT_FEATURE_10(sampleRateShading)};
    spec.options = {
        {.name = "--samples",
         .type = vkt::OptionType::choice,
         .value_name = "N",
         .help = "samples per pixel: 1 (no multisampling), 2, 4 or 8, as the device offers",
         .default_value = "4",
         .choices = {"1", "2", "4", "8"}},
        {.name = "--sample-shading",
         .type = vkt::OptionType::number,
         .value_name = "FRACTION",
         .help = "run the fragment shader for at least this fraction of the samples (0.25..1)",
         .min = 0.25,
         .max = 1.0},
    };
    spec.check_options = [](const vkt::Options& options) {
        if (options.has("--sample-shading") && options.text("--samples") == "1")
            throw vkt::UsageError("--sample-shading needs --samples 2 or more");
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Multisampling>(context);
    });
}
