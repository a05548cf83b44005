// Chapter 18: objects of n dimensions, on the CPU.
//
// A tesseract (the 4-cube) and a 24-cell side by side, turning in several of
// their six rotation planes at once; or one n-cube (--scene cube --dim N), or
// 250 of them (--scene many). The mathematics is plain C++ in common/
// (vkt/domains/ndim.hpp): meshes, transforms of n(n+3)/2 numbers, (n+1)x(n+1) model
// matrices, projection n -> 2 one dimension at a time. This file is the CPU
// path that uses it: every frame it builds each object's model matrix,
// transforms and projects every vertex, writes two 2D points per visible edge
// into this frame's host-visible vertex buffer, and draws them all with one
// vkCmdDraw of a LINE_LIST. Chapters 19 and 20 move that work to the GPU.

#include "vkt/domains/ndim.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/frame/stats.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/ndim_options.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace nd = vkt::ndim;

// [line-vertex]
// What the GPU gets: a point already projected to clip space and its colour.
// 12 bytes; the colour is four bytes unpacked to floats by the vertex input.
struct LineVertex {
    float x, y;
    uint32_t colour;  // R, G, B, A bytes, lowest first: VK_FORMAT_R8G8B8A8_UNORM
};
static_assert(sizeof(LineVertex) == 12);
// [/line-vertex]

// Linear colour (the _SRGB target encodes it) from the depth in the dropped
// dimensions: t = -1 (far from the eye on the last axis) blue, t = 1 (near)
// orange.
uint32_t depth_colour(float t) {
    t = std::clamp(0.5f + 0.5f * t, 0.0f, 1.0f);
    const float r = 0.10f + 0.90f * t, g = 0.30f + 0.15f * t, b = 1.00f - 0.90f * t;
    return uint32_t(std::lround(r * 255.0f)) | uint32_t(std::lround(g * 255.0f)) << 8 |
           uint32_t(std::lround(b * 255.0f)) << 16 | 0xff000000u;
}

// GLFW key codes for the controls (vkt/frame/input.hpp has the common ones).
constexpr int key_0 = 48, key_1 = 49, key_o = 79, key_r = 82, key_left_bracket = 91,
              key_right_bracket = 93, key_f1 = 290;

class NdimCpu : public vkt::Renderer {
public:
    explicit NdimCpu(const vkt::Context& context) : device_(context.device) {
        const auto& options = context.options;
        const nd::SceneChoice choice = nd::scene_choice(options);
        const std::string& scene = choice.scene;
        n_ = choice.n;
        still_ = choice.still;
        projection_ =
            choice.orthographic ? nd::Projection::orthographic : nd::Projection::perspective;
        naive_ = options.text("--matrix") == "naive";
        // The objects, their poses and spins, the eye distance and the view:
        // vkt::ndim::make_scene, shared with chapters 19 and 20.
        scene_ = nd::make_scene(scene, n_, still_);
        for (const nd::Mesh& mesh : scene_.meshes) radii_.push_back(mesh.radius());
        user_angles_.assign(size_t(nd::plane_count(n_)), 0.0f);
        user_offset_.assign(size_t(n_), 0.0f);

        // [vertex-buffers]
        // Every visible edge becomes two LineVertex, rewritten every frame: one
        // host-visible buffer per frame in flight, sized for every edge of
        // every object (edges behind the eye are left out, never added).
        const size_t edges = scene_.line_count();
        for (uint32_t i = 0; i < context.frames_in_flight; ++i)
            vertex_buffers_.push_back(vkt::create_host_buffer(
                context.gpu(), edges * 2 * sizeof(LineVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
        // [/vertex-buffers]
        std::fprintf(
            stderr,
            "18_ndim_cpu: %s scene, n = %d, %zu objects, %zu lines per frame, eye at %.3g\n",
            scene.c_str(), n_, scene_.objects.size(), edges, scene_.eye);

        // [line-pipeline]
        // The points arrive projected: the vertex shader only passes them on.
        // LINE_LIST: vertices 2k and 2k+1 make line k, one pixel wide.
        const VkVertexInputBindingDescription binding{
            .binding = 0, .stride = sizeof(LineVertex), .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {.location = 0,
             .binding = 0,
             .format = VK_FORMAT_R32G32_SFLOAT,
             .offset = offsetof(LineVertex, x)},
            {.location = 1,
             .binding = 0,
             .format = VK_FORMAT_R8G8B8A8_UNORM,
             .offset = offsetof(LineVertex, colour)},
        };
        layout_ = vkt::create_pipeline_layout(device_);
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "lines.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "lines.frag");
        const vkt::GraphicsPipelineDesc desc{
            .vertex = vertex,
            .fragment = fragment,
            .layout = layout_,
            .bindings = {&binding, 1},
            .attributes = attributes,
            .topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
            .color_formats = {context.color_format},
        };
        pipeline_ = vkt::create_graphics_pipeline(device_, desc);
        // [/line-pipeline]
        world_.resize(size_t(n_));
        benchmark_ = options.benchmark;
    }

    // With --benchmark, the CPU's share alone: the runner's frame time also
    // holds the wait for the GPU (and on lavapipe the GPU is the CPU too).
    ~NdimCpu() override {
        if (benchmark_)
            std::fprintf(stderr,
                         "18_ndim_cpu: CPU transform, project and write per frame, ms: %s\n",
                         vkt::json_summary(cpu_ms_).c_str());
    }

    void record(const vkt::Frame& frame) override {
        const float dt = float(frame.time - last_time_);
        last_time_ = frame.time;
        steer(frame.input, dt);
        if (!still_ && !paused_) spin_time_ += dt;

        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const float to_clip_x = 1.0f / (scene_.view_half_height * aspect),
                    to_clip_y = -1.0f / scene_.view_half_height;
        auto* out = static_cast<LineVertex*>(vertex_buffers_[frame.slot].mapped);
        size_t written = 0;
        const auto cpu_start = std::chrono::steady_clock::now();
        for (const nd::SceneObject& object : scene_.objects) {
            // [model-matrix]
            // This frame's transform: the start angles plus spin * time, plus
            // what the keys added; then the (n+1)x(n+1) matrix T * R * S.
            nd::Transform t = object.at(spin_time_);
            for (size_t p = 0; p < t.angles.size(); ++p) t.angles[p] += user_angles_[p];
            for (int k = 0; k < n_; ++k) t.position[size_t(k)] += user_offset_[size_t(k)];
            const nd::Matrix model = naive_ ? nd::model_matrix(t) : nd::model_matrix_by_rows(t);
            // [/model-matrix]

            // [transform-project]
            // Each vertex once: n(n+1) multiply-adds for the matrix, n - 2
            // divisions for the projection. The colour says how near the eye
            // the vertex is along the last axis, the first one dropped.
            const nd::Mesh& mesh = scene_.meshes[size_t(object.mesh)];
            projected_.resize(mesh.vertex_count());
            for (size_t i = 0; i < mesh.vertex_count(); ++i) {
                nd::transform_point(model, mesh.vertex(i), world_);
                Projected& p = projected_[i];
                float xy[2] = {0.0f, 0.0f};
                p.visible = nd::project_to_2d(world_, projection_, scene_.eye, xy);
                p.x = xy[0] * to_clip_x;
                p.y = xy[1] * to_clip_y;
                p.colour =
                    depth_colour((world_.back() - t.position.back()) / radii_[size_t(object.mesh)]);
            }
            // [/transform-project]

            // [write-lines]
            // Two points per edge whose ends are both in front of the eye.
            // Coherent memory: no flush, the queue submit makes it visible.
            for (const nd::Edge& edge : mesh.edges) {
                const Projected &a = projected_[edge.a], &b = projected_[edge.b];
                if (!a.visible || !b.visible) continue;
                out[written++] = {a.x, a.y, a.colour};
                out[written++] = {b.x, b.y, b.colour};
            }
            // [/write-lines]
        }
        if (benchmark_)
            cpu_ms_.push_back(std::chrono::duration<double, std::milli>(
                                  std::chrono::steady_clock::now() - cpu_start)
                                  .count());

        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.006f, 0.006f, 0.012f, 1.0f}});
        if (written > 0) {
            auto scope = frame.gpu_scope("raster");
            vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
            vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
            const VkDeviceSize offset = 0;
            const VkBuffer buffer = vertex_buffers_[frame.slot].buffer;
            vkCmdBindVertexBuffers(frame.cmd, 0, 1, &buffer, &offset);
            vkCmdDraw(frame.cmd, uint32_t(written), 1, 0, 0);
        }
        vkCmdEndRendering(frame.cmd);
    }

private:
    struct Projected {
        float x, y;
        uint32_t colour;
        bool visible;
    };

    // [controls]
    // In a window: keys 1..9, 0 turn the ten planes of the current page
    // (1 is plane (0,1) on page one), [ and ] change the page, F1..F12 move
    // along axes 0..11, Shift reverses, Space pauses the spin, O switches
    // perspective and orthographic, R resets. Headless, input is always
    // empty and the picture depends on the frame index alone.
    void steer(const vkt::Input& input, float dt) {
        const float sign = input.shift() ? -1.0f : 1.0f;
        const char* backwards = input.shift() ? " backwards" : "";
        const int planes = nd::plane_count(n_), pages = (planes + 9) / 10;
        if (input.went_down(key_right_bracket) || input.went_down(key_left_bracket)) {
            page_ = (page_ + (input.went_down(key_right_bracket) ? 1 : pages - 1)) % pages;
            const auto [i, j] = nd::plane_axes(n_, page_ * 10);
            std::fprintf(stderr, "18_ndim_cpu: keys 1..0 turn planes %d.. from (%d,%d)\n",
                         page_ * 10 + 1, i, j);
        }
        for (int key = 0; key < 10; ++key) {
            const int plane = page_ * 10 + key, code = key == 9 ? key_0 : key_1 + key;
            if (plane >= planes || !input.down(code)) continue;
            user_angles_[size_t(plane)] += sign * 1.0f * dt;  // 1 radian per second
            if (input.went_down(code)) {
                const auto [i, j] = nd::plane_axes(n_, plane);
                std::fprintf(stderr, "18_ndim_cpu: turning in plane (%d,%d)%s\n", i, j, backwards);
            }
        }
        for (int axis = 0; axis < std::min(n_, 12); ++axis) {
            if (!input.down(key_f1 + axis)) continue;
            user_offset_[size_t(axis)] += sign * 1.5f * dt;  // 1.5 units per second
            if (input.went_down(key_f1 + axis))
                std::fprintf(stderr, "18_ndim_cpu: moving along axis %d%s\n", axis, backwards);
        }
        if (input.went_down(vkt::key::space)) {
            paused_ = !paused_;
            std::fprintf(stderr, "18_ndim_cpu: spin %s\n", paused_ ? "paused" : "resumed");
        }
        if (input.went_down(key_o)) {
            const bool ortho = projection_ == nd::Projection::perspective;
            projection_ = ortho ? nd::Projection::orthographic : nd::Projection::perspective;
            std::fprintf(stderr, "18_ndim_cpu: %s projection\n",
                         ortho ? "orthographic" : "perspective");
        }
        if (input.went_down(key_r)) {
            const auto moved = [](const std::vector<float>& v) {
                return std::count_if(v.begin(), v.end(), [](float x) { return x != 0.0f; });
            };
            std::fprintf(stderr, "18_ndim_cpu: reset %td turned planes and %td moved axes\n",
                         moved(user_angles_), moved(user_offset_));
            std::fill(user_angles_.begin(), user_angles_.end(), 0.0f);
            std::fill(user_offset_.begin(), user_offset_.end(), 0.0f);
        }
    }
    // [/controls]

    VkDevice device_;
    int n_ = 4;
    bool still_ = false, naive_ = true, paused_ = false, benchmark_ = false;
    std::vector<double> cpu_ms_;
    nd::Projection projection_ = nd::Projection::perspective;
    nd::Scene scene_;
    std::vector<float> radii_;  // of each mesh: scales the depth colour
    std::vector<float> user_angles_, user_offset_;
    int page_ = 0;
    double last_time_ = 0.0;
    float spin_time_ = 0.0f;
    std::vector<float> world_;
    std::vector<Projected> projected_;
    std::vector<vkt::Buffer> vertex_buffers_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{
        .name = "18_ndim_cpu", .title = "18 - ndim_cpu", .input = vkt::InputUse::keys};
    // --scene, --dim, --projection and --motion: vkt/scene/ndim_options.hpp.
    spec.options = vkt::ndim::scene_options();
    spec.options.push_back(
        {.name = "--matrix",
         .type = vkt::OptionType::choice,
         .help = "build the model matrix from full products (O(n^5)) or row by row (O(n^3))",
         .default_value = "naive",
         .choices = {"naive", "rows"}});
    // --dim with the default scene contradicts it: said before any device exists.
    spec.check_options = [](const vkt::Options& options) { vkt::ndim::scene_choice(options); };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<NdimCpu>(context);
    });
}
