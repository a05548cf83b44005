// Chapter 11: a first-person camera.
//
// A courtyard to walk through: a checkered floor, a ring of coloured pillars
// round a stone plinth, crates, and four walls. In a window the mouse looks
// around (the cursor is captured), W A S D walk, Q and E go down and up,
// Shift runs, and Escape first gives the cursor back, then quits. Headless,
// and with --frames, there is no input: the camera follows a scripted path,
// a function of the frame's time only, so frame 10 is always the same
// picture. New here: vkt::FpsCamera (vkt/scene/fps_camera.hpp), the input snapshot
// the runner hands each frame, and speed scaled by frame time. The drawing
// is chapter 08's: one vertex buffer, a depth buffer, the matrix in a push
// constant (chapter 06).

#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/fps_camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace {

constexpr float pi = std::numbers::pi_v<float>;

struct Vertex {
    glm::vec3 position;  // world space: the scene never moves, only the camera
    glm::vec3 colour;
};

// Everything in one vertex and index buffer, in world coordinates.
struct Geometry {
    std::vector<Vertex> vertices;
    std::vector<uint16_t> indices;

    // Four corners counter-clockwise seen from the front (the culled side is
    // the back).
    void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 colour) {
        const auto first = uint16_t(vertices.size());
        for (glm::vec3 p : {a, b, c, d}) vertices.push_back({p, colour});
        indices.insert(indices.end(), {first, uint16_t(first + 1), uint16_t(first + 2), first,
                                       uint16_t(first + 2), uint16_t(first + 3)});
    }

    // A box from corner lo to corner hi. No lighting in this chapter, so each
    // face gets a fixed shade, as if the sun stood high, to the right and in
    // front: the top brightest, the bottom darkest.
    void box(glm::vec3 lo, glm::vec3 hi, glm::vec3 colour) {
        const glm::vec3 centre = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
        // +x, -x, +y, -y, +z, -z
        const float shade[6] = {0.8f, 0.6f, 1.0f, 0.4f, 0.9f, 0.5f};
        for (int face = 0; face < 6; ++face) {
            const int axis = face / 2;
            const float sign = face % 2 ? -1.0f : 1.0f;
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;  // u x v = n: counter-clockwise seen from outside
            auto corner = [&](float s, float t) { return centre + half * (n + s * u + t * v); };
            quad(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1), shade[face] * colour);
        }
    }
};

// The floor is 1 m tiles from -15 to 15 in x and z; tile (i, j), with
// i = floor(x) and j = floor(z), is light when i + j is even.
const glm::vec3 light_tile{0.55f, 0.55f, 0.52f}, dark_tile{0.22f, 0.23f, 0.25f};
const glm::vec3 sky{0.25f, 0.42f, 0.72f};  // the clear colour

Geometry courtyard() {
    Geometry g;
    for (int i = -15; i < 15; ++i)
        for (int j = -15; j < 15; ++j) {
            const float x = float(i), z = float(j);
            g.quad({x, 0, z}, {x, 0, z + 1}, {x + 1, 0, z + 1}, {x + 1, 0, z},
                   (i + j) % 2 == 0 ? light_tile : dark_tile);
        }
    // A stone plinth in the middle with a white cube on it.
    g.box({-1.2f, 0, -1.2f}, {1.2f, 0.8f, 1.2f}, {0.7f, 0.65f, 0.55f});
    g.box({-0.5f, 0.8f, -0.5f}, {0.5f, 1.8f, 0.5f}, {0.9f, 0.9f, 0.9f});
    // Eight pillars round it, 5 m out, each its own colour and one of three heights.
    const glm::vec3 colours[8] = {{0.8f, 0.15f, 0.1f},  {0.9f, 0.45f, 0.05f}, {0.85f, 0.75f, 0.1f},
                                  {0.15f, 0.6f, 0.15f}, {0.1f, 0.55f, 0.55f}, {0.15f, 0.25f, 0.8f},
                                  {0.5f, 0.15f, 0.7f},  {0.85f, 0.3f, 0.55f}};
    for (int k = 0; k < 8; ++k) {
        const float angle = (float(k) + 0.5f) * pi / 4;
        const glm::vec3 at{5 * std::sin(angle), 0, 5 * std::cos(angle)};
        const float height = 2.2f + 0.6f * float(k % 3);
        g.box(at - glm::vec3(0.4f, 0, 0.4f), at + glm::vec3(0.4f, height, 0.4f), colours[k]);
    }
    // Crates, 11 m out, between the pillars' directions.
    for (int k = 0; k < 6; ++k) {
        const float angle = float(k) * pi / 3 + 0.3f;
        const glm::vec3 at{11 * std::sin(angle), 0, 11 * std::cos(angle)};
        g.box(at - glm::vec3(0.6f, 0, 0.6f), at + glm::vec3(0.6f, 1.2f, 0.6f),
              {0.45f, 0.3f, 0.15f});
    }
    // Four walls, 20 m long, open at the corners.
    const glm::vec3 brick{0.55f, 0.2f, 0.15f};
    g.box({-10, 0, -14}, {10, 2.5f, -13.4f}, brick);
    g.box({-10, 0, 13.4f}, {10, 2.5f, 14}, brick);
    g.box({-14, 0, -10}, {-13.4f, 2.5f, 10}, brick);
    g.box({13.4f, 0, -10}, {14, 2.5f, 10}, brick);
    return g;
}

// [script]
// Headless: a walk round the plinth, 8 m out (between the pillars and the
// crates), at eye height, one lap every 2 pi / 0.3 = 21 s, looking mostly at
// the middle with a slow sway of the head. Only the time decides the pose,
// so every run draws the same frames.
vkt::FpsCamera scripted_camera(float t) {
    const float around = 0.3f * t;  // the walker's angle about the y axis
    vkt::FpsCamera camera;
    camera.position = {8 * std::sin(around), 1.7f, 8 * std::cos(around)};
    camera.yaw = -around + 0.35f * std::sin(0.4f * t);  // yaw -around faces the middle
    camera.pitch = -0.1f + 0.06f * std::sin(0.9f * t);
    return camera;
}
// [/script]

// Where the interactive camera starts: where the script starts.
const vkt::FpsCamera start = scripted_camera(0.0f);

struct Push {
    glm::mat4 clip_from_world;
};

class Camera : public vkt::Renderer {
public:
    explicit Camera(const vkt::Context& context)
        : physical_(context.physical),
          device_(context.device),
          speed_(float(context.options.number("--speed"))),
          sensitivity_(float(context.options.number("--sensitivity"))) {
        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);

        const Geometry g = courtyard();
        index_count_ = uint32_t(g.indices.size());
        const vkt::Gpu gpu = context.gpu();
        vertex_buffer_ =
            vkt::create_device_buffer(gpu, g.vertices.data(), g.vertices.size() * sizeof(Vertex),
                                      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ =
            vkt::create_device_buffer(gpu, g.indices.data(), g.indices.size() * sizeof(uint16_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        const VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(device_, {}, {&range, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "scene.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "scene.frag");
        const VkVertexInputBindingDescription binding{0, sizeof(Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, colour)},
        };
        pipeline_ =
            vkt::create_graphics_pipeline(device_, {
                                                       .vertex = vertex,
                                                       .fragment = fragment,
                                                       .layout = layout_,
                                                       .bindings = {&binding, 1},
                                                       .attributes = attributes,
                                                       .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                       .color_formats = {context.color_format},
                                                       .depth_format = depth_format_,
                                                   });
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
    }

    void record(const vkt::Frame& frame) override {
        const vkt::FpsCamera camera = update_camera(frame);
        // [camera-matrix]
        // The view matrix from the camera's pose, then chapter 08's projection.
        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const Push push{vkt::vulkan_perspective(glm::radians(60.0f), aspect, 0.05f, 100.0f) *
                        camera.view()};
        // [/camera-matrix]

        vkt::begin_depth_frame(frame.cmd, depth_.image);
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{sky.r, sky.g, sky.b, 1.0f}}, depth_.view);
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdPushConstants(frame.cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdDrawIndexed(frame.cmd, index_count_, 1, 0, 0, 0);
        vkCmdEndRendering(frame.cmd);
    }

private:
    // [interactive]
    vkt::FpsCamera update_camera(const vkt::Frame& frame) {
        const vkt::Input& input = frame.input;
        // The script plays until the user is there: in an open-ended window
        // run the runner captures the cursor before the first frame. Headless
        // and under --frames every snapshot is empty, so the script plays on.
        if (!interactive_ && (input.cursor_captured || input.held.any())) {
            interactive_ = true;
            last_time_ = frame.time;
        }
        if (!interactive_) return scripted_camera(float(frame.time));

        // Seconds since the last frame, from the runner's clock. Capped, so
        // that after a stall (the window dragged, the machine busy) the camera
        // does not jump through a wall in one step.
        const float dt = float(std::clamp(frame.time - last_time_, 0.0, 0.1));
        last_time_ = frame.time;
        const float speed = input.shift() ? 3.0f * speed_ : speed_;
        camera_.update(input, dt, speed, sensitivity_);

        // Say when the cursor changes hands (the window test waits for it),
        // and where the camera stands then.
        if (input.cursor_captured != captured_) {
            captured_ = input.cursor_captured;
            if (captured_)
                std::fprintf(stderr,
                             "11_camera: cursor captured: the mouse looks, W A S D walk, Q E down "
                             "and up, Shift runs, Escape releases the cursor\n");
            else
                std::fprintf(stderr,
                             "11_camera: cursor released at (%.4f, %.4f, %.4f), yaw %.4f, pitch "
                             "%.4f: click in the window to capture it again, Escape quits\n",
                             camera_.position.x, camera_.position.y, camera_.position.z,
                             camera_.yaw, camera_.pitch);
        }
        return camera_;
    }
    // [/interactive]

    VkPhysicalDevice physical_;
    VkDevice device_;
    float speed_, sensitivity_;
    vkt::FpsCamera camera_ = start;
    bool interactive_ = false;  // has the user taken over from the script?
    bool captured_ = false;     // the cursor, as the last frame saw it
    double last_time_ = 0;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    uint32_t index_count_ = 0;
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "11_camera", .title = "11 - camera"};
    spec.input = vkt::InputUse::mouse_look;  // the runner captures the cursor in a window
    // [/spec]
    // The depth image's DEPTH_ATTACHMENT_OPTIMAL layout (vkt::begin_depth_frame).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        {.name = "--speed",
         .type = vkt::OptionType::number,
         .value_name = "M/S",
         .help = "walking speed in a window, in metres per second (Shift: three times it)",
         .default_value = "3",
         .min = 0.1,
         .max = 50},
        {.name = "--sensitivity",
         .type = vkt::OptionType::number,
         .value_name = "RAD",
         .help = "mouse look in a window, in radians per pixel of mouse movement",
         .default_value = "0.0025",
         .min = 0.0001,
         .max = 0.05},
    };
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Camera>(context);
    });
}
