// Chapter 14: physics.
//
// A thousand boxes of several sizes, each turned at random, fall onto a floor
// and a ramp, tumble over each other and settle into heaps; P (or --scene stacks)
// adds a pyramid and a tall tower beside them. The physics is plain C++ in
// common/ (vkt/domains/physics*.hpp: rigid bodies that turn, sort-and-sweep,
// the separating axis test and contact clipping, sequential impulses,
// sleeping); this file shows the two things that connect it to the screen.
// The fixed time step: the world advances in steps of exactly 1/120 s however
// fast frames come. And the new Vulkan concept, instancing: one cube mesh, one
// vkCmdDrawIndexed with instanceCount = the number of boxes, and a second
// vertex buffer that advances once per box instead of once per vertex,
// holding each box's position, size, orientation and colour, rewritten every
// frame.

#include "vkt/domains/physics_scene.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/camera_math.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

namespace physics = vkt::physics;

// The cube every box is drawn from: 24 corners (4 per face, so each face has
// its own normal) and 36 indices, counter-clockwise seen from outside.
struct Vertex {
    glm::vec3 corner;  // -1..1: scaled by each box's half extents
    glm::vec3 normal;
};

void make_cube(std::vector<Vertex>& vertices, std::vector<uint16_t>& indices) {
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const float sign = face % 2 ? -1.0f : 1.0f;
        glm::vec3 n(0.0f), u(0.0f), v(0.0f);
        n[axis] = sign;
        u[(axis + 1) % 3] = 1.0f;
        v[(axis + 2) % 3] = sign;
        const auto first = uint16_t(vertices.size());
        for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
            vertices.push_back({n + c.x * u + c.y * v, n});
        indices.insert(indices.end(), {first, uint16_t(first + 1), uint16_t(first + 2), first,
                                       uint16_t(first + 2), uint16_t(first + 3)});
    }
}

// [instance-struct]
// What the vertex shader gets once per box: 44 bytes, tightly packed. The
// orientation is the body's unit quaternion (x, y, z, w); the colour is four
// bytes that the vertex input unpacks to four floats.
struct Instance {
    glm::vec3 position;
    glm::vec3 half_extents;
    glm::vec4 orientation;
    uint32_t colour;  // R, G, B, A bytes, lowest first: VK_FORMAT_R8G8B8A8_UNORM
};
static_assert(sizeof(Instance) == 44);
// [/instance-struct]

// A colour per box from a small palette, lighter or darker by its index; the
// static bodies (the floor, the ramp) are greys. Linear values: the _SRGB
// target encodes them.
uint32_t box_colour(const physics::Body& body, uint32_t index) {
    if (body.is_static()) return index == 0 ? 0xff595959u : 0xff3a3a3au;
    static const uint32_t palette[] = {0xc03020, 0x2060c0, 0x30a040, 0xd0a020, 0x8040b0, 0x20a0a0};
    const uint32_t hash = index * 2654435761u;  // Knuth's multiplicative hash: mixes neighbours
    const uint32_t rgb = palette[(hash >> 16) % 6u];
    const uint32_t scale = 160u + (hash >> 8) % 96u;  // 160..255 of 255
    uint32_t out = 0xff000000u;
    for (uint32_t shift : {0u, 8u, 16u})
        out |= (((rgb >> (16u - shift)) & 0xffu) * scale / 255u) << shift;
    return out;
}

// [fixed-step-constants]
// 120 steps of 1/120 s per simulated second, whatever the frame rate. At most
// 8 steps per frame: a machine that cannot keep up slows the world down
// instead of falling ever further behind (each late frame asking for more
// steps, which make it later still).
constexpr double kStepsPerSecond = 120.0;
constexpr uint64_t kMaxStepsPerFrame = 8;
// [/fixed-step-constants]

class Boxes : public vkt::Renderer {
public:
    explicit Boxes(const vkt::Context& context)
        : physical_(context.physical), device_(context.device) {
        const auto& options = context.options;
        physics::Settings settings;
        settings.time_step = float(1.0 / kStepsPerSecond);
        settings.broad_phase = options.text("--broadphase") == "brute"
                                   ? physics::BroadPhase::brute_force
                                   : physics::BroadPhase::sweep_and_prune;
        world_ = physics::World(settings);
        const auto count = uint32_t(options.integer("--count"));
        scene_ = physics::add_falling_boxes(world_, count);
        const bool stacks = options.text("--scene") == "stacks";
        if (stacks) physics::add_stacks(world_, scene_);
        stacks_added_ = stacks;
        // --warmup: simulate this much before the first frame (the tests use
        // it to photograph the boxes after they have settled).
        const auto warmup = uint64_t(std::llround(options.number("--warmup") * kStepsPerSecond));
        for (uint64_t i = 0; i < warmup; ++i) world_.step();
        std::fprintf(stderr,
                     "14_physics: %u boxes%s, %s, %g steps/s, %llu warm-up steps, %zu contact "
                     "points, %zu awake\n",
                     count, stacks ? " and the stacks" : "",
                     options.text("--broadphase") == "brute" ? "brute force" : "sort-and-sweep",
                     kStepsPerSecond, (unsigned long long)warmup, world_.contact_points(),
                     world_.awake_count());
        // The camera backs off as the heaps grow.
        eye_distance_ = 1.7f * scene_.extent;

        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);

        std::vector<Vertex> vertices;
        std::vector<uint16_t> indices;
        make_cube(vertices, indices);
        index_count_ = uint32_t(indices.size());
        const vkt::Gpu gpu = context.gpu();
        cube_vertices_ =
            vkt::create_device_buffer(gpu, vertices.data(), vertices.size() * sizeof(Vertex),
                                      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        cube_indices_ =
            vkt::create_device_buffer(gpu, indices.data(), indices.size() * sizeof(uint16_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        // [instance-buffers]
        // One instance buffer per frame in flight: the CPU rewrites frame N's
        // while the GPU may still be reading frame N - 1's. Host-visible and
        // coherent, mapped for good; usage VERTEX_BUFFER like any vertex data.
        // Room for the stacks too, which P may add later (75 boxes).
        const std::size_t most = world_.bodies().size() + (stacks ? 0 : 75);
        for (uint32_t i = 0; i < context.frames_in_flight; ++i)
            instance_buffers_.push_back(vkt::create_host_buffer(gpu, most * sizeof(Instance),
                                                                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
        // [/instance-buffers]

        // [vertex-input]
        // Two bindings. Binding 0 steps once per vertex: the cube's corner and
        // normal. Binding 1 steps once per INSTANCE: every vertex of box i
        // reads element i, so all 24 corners of a box see the same position,
        // size, orientation and colour.
        const VkVertexInputBindingDescription bindings[] = {
            {.binding = 0, .stride = sizeof(Vertex), .inputRate = VK_VERTEX_INPUT_RATE_VERTEX},
            {.binding = 1, .stride = sizeof(Instance), .inputRate = VK_VERTEX_INPUT_RATE_INSTANCE},
        };
        const VkVertexInputAttributeDescription attributes[] = {
            {.location = 0,
             .binding = 0,
             .format = VK_FORMAT_R32G32B32_SFLOAT,
             .offset = offsetof(Vertex, corner)},
            {.location = 1,
             .binding = 0,
             .format = VK_FORMAT_R32G32B32_SFLOAT,
             .offset = offsetof(Vertex, normal)},
            {.location = 2,
             .binding = 1,
             .format = VK_FORMAT_R32G32B32_SFLOAT,
             .offset = offsetof(Instance, position)},
            {.location = 3,
             .binding = 1,
             .format = VK_FORMAT_R32G32B32_SFLOAT,
             .offset = offsetof(Instance, half_extents)},
            {.location = 4,
             .binding = 1,
             .format = VK_FORMAT_R32G32B32A32_SFLOAT,
             .offset = offsetof(Instance, orientation)},
            // UNORM: the bytes 0..255 arrive in the shader as floats 0..1.
            {.location = 5,
             .binding = 1,
             .format = VK_FORMAT_R8G8B8A8_UNORM,
             .offset = offsetof(Instance, colour)},
        };
        // [/vertex-input]

        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        layout_ = vkt::create_pipeline_layout(device_, {}, {&push, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "boxes.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "boxes.frag");
        pipeline_ =
            vkt::create_graphics_pipeline(device_, {
                                                       .vertex = vertex,
                                                       .fragment = fragment,
                                                       .layout = layout_,
                                                       .bindings = bindings,
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
        // P: the pyramid and the tower, once (in a window; --scene stacks headless).
        if (frame.input.went_down('P')) {
            if (!stacks_added_) {
                const std::size_t before = world_.bodies().size();
                physics::add_stacks(world_, scene_);
                stacks_added_ = true;
                std::fprintf(stderr,
                             "14_physics: P: added a 10-level pyramid and a 20-box tower (%zu "
                             "boxes, %zu bodies now)\n",
                             world_.bodies().size() - before, world_.bodies().size());
            } else {
                std::fprintf(stderr,
                             "14_physics: P: the pyramid and the tower are already there\n");
            }
        }
        // [fixed-step]
        // The accumulator, counted in whole steps: the steps due by now are
        // time * 120, rounded down; run the ones not run yet. Headless, time
        // is frame index / 60, so every frame runs exactly 2 steps and the
        // same frame always shows the same world.
        const auto due = uint64_t(std::floor(frame.time * kStepsPerSecond + 1e-6));
        if (due > steps_done_ + kMaxStepsPerFrame) steps_done_ = due - kMaxStepsPerFrame;
        for (; steps_done_ < due; ++steps_done_) world_.step();
        // [/fixed-step]

        // [write-instances]
        // This frame's slot finished its last frame (the runner waited for its
        // fence), so its buffer is free to overwrite. Coherent memory: no
        // flush; the queue submit makes the writes visible to the GPU.
        auto* instances = static_cast<Instance*>(instance_buffers_[frame.slot].mapped);
        const auto bodies = world_.bodies();
        for (uint32_t i = 0; i < bodies.size(); ++i) {
            const glm::quat q = bodies[i].orientation;
            instances[i] = {bodies[i].position, bodies[i].half_extents,
                            glm::vec4(q.x, q.y, q.z, q.w), box_colour(bodies[i], i)};
        }
        // [/write-instances]

        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const float d = eye_distance_;
        const glm::mat4 view = glm::lookAt(glm::vec3(0.45f * d, 0.8f * d, 1.3f * d),
                                           glm::vec3(0.0f, 0.0f, -0.1f * d), glm::vec3(0, 1, 0));
        const glm::mat4 view_projection =
            vkt::vulkan_perspective(glm::radians(45.0f), aspect, 0.1f, 8.0f * d) * view;

        vkt::begin_depth_frame(frame.cmd, depth_.image);
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.30f, 0.45f, 0.65f, 1.0f}}, depth_.view);
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdPushConstants(frame.cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &view_projection);
        // [draw]
        // Binding 0: the cube. Binding 1: this frame's boxes. Then one draw:
        // 36 indices, once per body (the floor and the ramp are boxes too).
        const VkBuffer buffers[] = {cube_vertices_.buffer, instance_buffers_[frame.slot].buffer};
        const VkDeviceSize offsets[] = {0, 0};
        vkCmdBindVertexBuffers(frame.cmd, 0, 2, buffers, offsets);
        vkCmdBindIndexBuffer(frame.cmd, cube_indices_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdDrawIndexed(frame.cmd, index_count_, /*instanceCount=*/uint32_t(bodies.size()),
                         /*firstIndex=*/0, /*vertexOffset=*/0, /*firstInstance=*/0);
        // [/draw]
        vkCmdEndRendering(frame.cmd);
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    physics::World world_;
    physics::Scene scene_;
    bool stacks_added_ = false;
    uint64_t steps_done_ = 0;
    float eye_distance_ = 12.0f;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    uint32_t index_count_ = 0;
    vkt::Buffer cube_vertices_;
    vkt::Buffer cube_indices_;
    std::vector<vkt::Buffer> instance_buffers_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{
        .name = "14_physics", .title = "14 - Physics", .input = vkt::InputUse::keys};
    // The depth barrier's DEPTH_ATTACHMENT_OPTIMAL layout (chapter 08).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        // 65536: 2.8 MiB of instance data per frame in flight, but a physics
        // step of that many boxes takes far longer than 1/120 s on one core
        // (benchmarks/physics.md): the world then runs slower than real time.
        {.name = "--count",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many boxes fall",
         .default_value = "1000",
         .min = 1,
         .max = 65536},
        {.name = "--broadphase",
         .type = vkt::OptionType::choice,
         .help = "find touching pairs by sort-and-sweep or by testing every pair",
         .default_value = "sap",
         .choices = {"sap", "brute"}},
        {.name = "--warmup",
         .type = vkt::OptionType::number,
         .value_name = "SECONDS",
         .help = "simulate this long before the first frame",
         .default_value = "0",
         .min = 0,
         .max = 60},
        {.name = "--scene",
         .type = vkt::OptionType::choice,
         .help = "stacks: the heaps plus a 10-level pyramid and a 20-box tower (P in a window)",
         .default_value = "heaps",
         .choices = {"heaps", "stacks"}},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Boxes>(context);
    });
}
