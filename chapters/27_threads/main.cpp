// Chapter 27: threads.
//
// Thousands of objects on a floor, each with its own draw and its own push
// constants, recorded every frame by N threads at once (--threads N):
//
// - A command pool belongs to one thread at a time (Vulkan leaves its
//   locking to the application), so each thread gets a pool of its own, per
//   frame slot: thread t resets and records only pools_[slot][t].
// - Each thread records its share of the objects into a SECONDARY command
//   buffer that inherits the frame's dynamic rendering (its formats), and the
//   frame's primary command buffer, once every thread is done (the join),
//   begins rendering and executes them in order.
// - The shares are consecutive runs of the objects, executed in thread order,
//   so the GPU sees the same draws in the same order at every N: the same
//   picture, to the bit.
//
// And a pipeline cache: with --pipeline-cache FILE the compiled pipeline is
// kept in FILE and read back at the next start (pipeline_cache.hpp).
// workers.hpp is the crew of threads (plain C++).

#include "pipeline_cache.hpp"
#include "workers.hpp"

#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/frame/stats.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/camera_math.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

namespace {

using PipelineCache = vkt::Owned<VkPipelineCache, VkDevice, vkDestroyPipelineCache>;

// The push constants of one draw (threads.vert): 96 of the 128 bytes every
// device guarantees. The CPU multiplies each object's matrix with the camera's:
// per-object work that the threads share too.
struct Push {
    glm::mat4 clip_from_object;
    glm::vec4 colour;
    glm::vec2 turn;  // cos, sin
    glm::vec2 pad;
};
static_assert(sizeof(Push) == 96 && offsetof(Push, turn) == 80);

enum Shape : uint32_t { floor_shape, cube, sphere, cylinder, torus, shape_count };

// One object: where it stands, its size, its shape and colour, and how it turns.
struct Object {
    glm::vec3 position;
    float size;
    Shape shape;
    glm::vec3 colour;    // linear
    float phase, speed;  // turn = phase + speed * time, radians
};

// A small integer hash: the same scene on every machine.
uint32_t hash(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    return x ^ (x >> 16);
}

// Object 0 the floor, then grid x grid shapes, 2 units apart.
std::vector<Object> make_objects(uint32_t grid) {
    const glm::vec3 palette[] = {{0.80f, 0.25f, 0.20f}, {0.90f, 0.60f, 0.15f},
                                 {0.25f, 0.65f, 0.30f}, {0.20f, 0.45f, 0.80f},
                                 {0.60f, 0.35f, 0.75f}, {0.85f, 0.85f, 0.80f}};
    const float half = float(grid);
    std::vector<Object> objects{{{0, 0, 0}, 2.0f * half, floor_shape, {0.5f, 0.5f, 0.5f}, 0, 0}};
    for (uint32_t i = 0; i < grid * grid; ++i) {
        const uint32_t h = hash(i), g = hash(h);
        const float size = 0.6f + 0.4f * float(h % 1000) / 1000.0f;
        const uint32_t column = i % grid, row = i / grid;  // whole numbers
        objects.push_back(
            {{2.0f * float(column) + 1.0f - half, 0.5f * size, 2.0f * float(row) + 1.0f - half},
             size,
             Shape(1 + (h >> 10) % (shape_count - 1)),
             palette[(g >> 4) % 6],
             float((g >> 8) % 628) / 100.0f,
             0.5f + float((h >> 20) % 100) / 100.0f});
    }
    return objects;
}

class Threads : public vkt::Renderer {
public:
    explicit Threads(const vkt::Context& context)
        : physical_(context.physical),
          device_(context.device),
          color_format_(context.color_format),
          workers_(uint32_t(context.options.integer("--threads"))) {
        const vkt::Gpu gpu = context.gpu();
        const auto grid = uint32_t(context.options.integer("--grid"));
        benchmark_ = context.options.benchmark;
        objects_ = make_objects(grid);
        half_width_ = float(grid);

        // Chapter 12's shapes in one vertex and one index buffer.
        vkt::shapes::MeshBuilder builder;
        meshes_[floor_shape] = builder.floor(1);
        meshes_[cube] = builder.cube();
        meshes_[sphere] = builder.sphere(12, 8);
        meshes_[cylinder] = builder.cylinder(12);
        meshes_[torus] = builder.torus(16, 8, 0.15f);
        vertex_buffer_ = vkt::create_device_buffer(
            gpu, builder.vertices.data(), builder.vertices.size() * sizeof(vkt::shapes::Vertex),
            VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ = vkt::create_device_buffer(gpu, builder.indices.data(),
                                                  builder.indices.size() * sizeof(uint16_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        // [pipeline-cache]
        // The cache starts with the file's bytes where it has good ones, else
        // empty; the pipeline is created through it, and what it then holds
        // is written back. All of this chapter's pipelines exist after
        // start-up, so the cache is saved here and not at exit.
        std::vector<char> initial;
        const std::string cache_path =
            context.options.has("--pipeline-cache") ? context.options.text("--pipeline-cache") : "";
        PipelineCache cache;
        if (!cache_path.empty()) {
            initial = ch27::load_cache_file(cache_path, context.properties);
            const VkPipelineCacheCreateInfo cache_info{
                .sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO,
                .initialDataSize = initial.size(),
                .pInitialData = initial.data(),
            };
            VkPipelineCache handle;
            VKT_CHECK(vkCreatePipelineCache(device_, &cache_info, nullptr, &handle));
            cache = PipelineCache(device_, handle);
        }
        // [/pipeline-cache]

        // The pipeline of chapters 08 and 12 (vertex input, depth, culling).
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(device_, {}, {&push, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "threads.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "threads.frag");
        const VkVertexInputBindingDescription binding{0, sizeof(vkt::shapes::Vertex),
                                                      VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(vkt::shapes::Vertex, normal)},
        };
        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);
        const auto start = std::chrono::steady_clock::now();
        pipeline_ = vkt::create_graphics_pipeline(device_, {.vertex = vertex,
                                                            .fragment = fragment,
                                                            .layout = layout_,
                                                            .bindings = {&binding, 1},
                                                            .attributes = attributes,
                                                            .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                            .color_formats = {color_format_},
                                                            .depth_format = depth_format_,
                                                            .cache = cache});
        const double pipeline_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        std::fprintf(stderr, "27_threads: the pipeline took %.1f ms to create (%s)\n", pipeline_ms,
                     cache_path.empty() ? "no pipeline cache"
                     : initial.empty()  ? "an empty pipeline cache"
                                        : "a pipeline cache loaded from the file");
        if (cache) ch27::save_cache_file(cache_path, device_, cache);

        // [command-pools]
        // One pool per thread per frame slot. A pool, and every command buffer
        // from it, may be used by one thread at a time; the slot keeps a frame's
        // buffers from being reset while the GPU may still run them (the runner
        // waits for the slot's fence before record()). TRANSIENT: its buffers
        // are re-recorded every time they are used.
        const uint32_t threads = workers_.count();
        for (uint32_t slot = 0; slot < context.frames_in_flight; ++slot)
            for (uint32_t t = 0; t < threads; ++t) {
                const VkCommandPoolCreateInfo pool_info{
                    .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                    .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                    .queueFamilyIndex = context.queue_family,
                };
                VkCommandPool pool;
                VKT_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &pool));
                pools_.emplace_back(device_, pool);
                const VkCommandBufferAllocateInfo allocate{
                    .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                    .commandPool = pool,
                    .level = VK_COMMAND_BUFFER_LEVEL_SECONDARY,
                    .commandBufferCount = 1,
                };
                VkCommandBuffer secondary;
                VKT_CHECK(vkAllocateCommandBuffers(device_, &allocate, &secondary));
                secondaries_.push_back(secondary);  // freed with its pool
            }
        // [/command-pools]

        // [shares]
        // Thread t draws objects [first_[t], first_[t + 1]): consecutive runs
        // of as equal a size as whole objects allow, in order.
        const auto count = uint32_t(objects_.size());
        for (uint32_t t = 0; t <= threads; ++t)
            first_.push_back(uint32_t(uint64_t(count) * t / threads));
        // [/shares]
        std::fprintf(stderr,
                     "27_threads: %u objects (%u x %u and the floor), one draw each, recorded by "
                     "%u thread%s into secondary command buffers (%u command pools: %u per frame "
                     "slot)\n",
                     count, grid, grid, threads, threads == 1 ? "" : "s", uint32_t(pools_.size()),
                     threads);
    }

    ~Threads() override {
        if (record_ms_.empty()) return;
        const vkt::Summary cpu = vkt::summarize(record_ms_);
        std::fprintf(stderr,
                     "27_threads: recording the draws on %u thread%s took %.4f ms median, %.4f ms "
                     "p95 on the CPU (%zu frames)\n",
                     workers_.count(), workers_.count() == 1 ? "" : "s", cpu.median, cpu.p95,
                     record_ms_.size());
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
    }

    void record(const vkt::Frame& frame) override {
        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const float angle = 0.6f + 0.05f * float(frame.time), r = 0.8f * half_width_;
        const glm::mat4 view =
            glm::lookAt(glm::vec3(r * std::sin(angle), 0.35f * half_width_, r * std::cos(angle)),
                        glm::vec3(0.0f), glm::vec3(0, 1, 0));
        const glm::mat4 view_projection =
            vkt::vulkan_perspective(glm::radians(50.0f), aspect, 0.1f, 4.0f * half_width_) * view;

        // [fork-join]
        // Every thread records its share into its own secondary command
        // buffer; run() returns when all are done. Then, and only then, the
        // primary may name them.
        const uint32_t threads = workers_.count();
        const auto start = std::chrono::steady_clock::now();
        workers_.run([&](uint32_t t) { record_share(frame, view_projection, t); });
        if (benchmark_)
            record_ms_.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        // [/fork-join]

        auto scope = frame.gpu_scope("draw");
        vkt::begin_depth_frame(frame.cmd, depth_.image);
        // [execute]
        // Rendering begun with SECONDARY_COMMAND_BUFFERS: inside it this
        // primary records nothing but vkCmdExecuteCommands, which runs the
        // secondaries one after another, in the order given.
        const VkRenderingAttachmentInfo colour{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = frame.target_view,
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.30f, 0.45f, 0.65f, 1.0f}}},
        };
        const VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = depth_.view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
            .clearValue = {.depthStencil = {1.0f, 0}},
        };
        const VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .flags = VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT,
            .renderArea = {{0, 0}, frame.extent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &colour,
            .pDepthAttachment = &depth,
        };
        vkCmdBeginRendering(frame.cmd, &rendering);
        vkCmdExecuteCommands(frame.cmd, threads, &secondaries_[size_t(frame.slot) * threads]);
        vkCmdEndRendering(frame.cmd);
        // [/execute]
    }

private:
    // [secondary]
    // Thread t's share of a frame: only its own pool and command buffer, the
    // objects (read only), the frame (read only) and its own Push on its stack.
    void record_share(const vkt::Frame& frame, const glm::mat4& view_projection, uint32_t t) {
        const uint32_t threads = workers_.count();
        VkCommandBuffer cmd = secondaries_[size_t(frame.slot) * threads + t];
        VKT_CHECK(vkResetCommandPool(device_, pools_[size_t(frame.slot) * threads + t], 0));
        // What the secondary draws into, which it cannot see: the formats of
        // the rendering it will run inside (they must match it exactly).
        const VkCommandBufferInheritanceRenderingInfo inherit_rendering{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_RENDERING_INFO,
            .colorAttachmentCount = 1,
            .pColorAttachmentFormats = &color_format_,
            .depthAttachmentFormat = depth_format_,
            .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT,
        };
        const VkCommandBufferInheritanceInfo inheritance{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO,
            .pNext = &inherit_rendering,
        };
        // RENDER_PASS_CONTINUE: it runs entirely inside rendering begun by
        // the primary (without it, the inheritance above would be ignored).
        const VkCommandBufferBeginInfo begin{
            .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
            .flags = VK_COMMAND_BUFFER_USAGE_RENDER_PASS_CONTINUE_BIT |
                     VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
            .pInheritanceInfo = &inheritance,
        };
        VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
        // Nothing is inherited from the primary's state or another secondary:
        // each binds its pipeline and buffers and sets its viewport itself.
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(cmd, frame.extent);
        const VkBuffer vertices = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertices, &offset);
        vkCmdBindIndexBuffer(cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        for (uint32_t i = first_[t]; i < first_[t + 1]; ++i) {
            const Object& o = objects_[i];
            const float turn = o.phase + o.speed * float(frame.time);
            const glm::vec3 scale =
                o.shape == floor_shape ? glm::vec3(o.size, 1.0f, o.size) : glm::vec3(o.size);
            const Push push{view_projection * vkt::transform(o.position, turn, {0, 1, 0}, scale),
                            glm::vec4(o.colour, 1.0f), glm::vec2(std::cos(turn), std::sin(turn)),
                            glm::vec2(0.0f)};
            vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push), &push);
            const vkt::shapes::MeshRange& mesh = meshes_[o.shape];
            vkCmdDrawIndexed(cmd, mesh.index_count, 1, mesh.first_index, 0, 0);
        }
        VKT_CHECK(vkEndCommandBuffer(cmd));
    }
    // [/secondary]

    VkPhysicalDevice physical_;
    VkDevice device_;
    VkFormat color_format_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    ch27::Workers workers_;
    bool benchmark_ = false;
    std::vector<double> record_ms_;  // --benchmark: fork to join, per frame
    std::vector<Object> objects_;
    float half_width_ = 1.0f;
    vkt::shapes::MeshRange meshes_[shape_count];
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    vkt::Image depth_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
    std::vector<vkt::CommandPool> pools_;       // [slot * threads + t]
    std::vector<VkCommandBuffer> secondaries_;  // [slot * threads + t], from pools_
    std::vector<uint32_t> first_;               // thread t's objects: first_[t] .. first_[t + 1]
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    // By default one thread per processor the system reports (at most 64).
    const unsigned cores = std::clamp(std::thread::hardware_concurrency(), 1u, 64u);
    vkt::ChapterSpec spec{.name = "27_threads", .title = "27 - threads"};
    // The depth barrier's DEPTH_ATTACHMENT_OPTIMAL layout (chapter 08).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    spec.options = {
        {.name = "--threads",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "threads that record the draws (default: one per processor)",
         .default_value = std::to_string(cores),
         .min = 1,
         .max = 64},
        {.name = "--grid",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "objects on an N x N grid",
         .default_value = "64",
         .min = 1,
         .max = 256},
        {.name = "--pipeline-cache",
         .type = vkt::OptionType::text,
         .value_name = "FILE",
         .help = "keep the compiled pipeline in FILE and start from it next time"},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Threads>(context);
    });
}
