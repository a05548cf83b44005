// Chapter 15: bindless.
//
// A thousand objects (cubes, pyramids, octahedra) on a grid, textured from
// dozens of textures, drawn by ONE command. Three ideas make that possible:
//
// - Descriptor indexing: every texture sits in one runtime-sized array of
//   sampled images, bound once; the shader picks one by index (nonuniformEXT).
//   The set is partially bound, variable-sized and updated after binding:
//   textures "arrive" a few per frame while earlier frames are still in flight.
// - Buffer device address: vertices and per-object records are read through
//   64-bit GPU pointers passed in push constants; no vertex input state, no
//   storage-buffer descriptors.
// - Indirect multi-draw: one vkCmdDrawIndexedIndirect reads a draw per object
//   from a buffer. --draw loop issues the same draws one vkCmdDrawIndexed at a
//   time instead, for the comparison the book measures.
//
// scene.hpp builds the objects (plain C++); address_buffer.hpp makes the
// buffers the shaders read through GPU addresses.

#include "address_buffer.hpp"
#include "scene.hpp"

#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/frame/stats.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/procedural_texture.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"
#include "vkt/scene/camera_math.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace {

// [push]
// The push constants: the two buffers' GPU addresses travel as plain 64-bit
// integers. 88 bytes of the 128 every device guarantees.
struct Push {
    glm::mat4 view_projection;
    VkDeviceAddress vertices;
    VkDeviceAddress objects;
    uint32_t resident_textures;
    uint32_t pad;
};
static_assert(offsetof(Push, vertices) == 64 && offsetof(Push, resident_textures) == 80);
// [/push]

// The largest texture array the layout allows; the set allocates only what it
// uses (a variable descriptor count). Far below the limits: a device with the
// descriptorIndexing feature allows at least 500,000 update-after-bind
// sampled images per shader stage.
constexpr uint32_t kMaxTextures = 1024;
// Descriptor writes per frame while the textures "stream in" (see record()).
constexpr uint32_t kTexturesPerFrame = 8;

class Bindless : public vkt::Renderer {
public:
    explicit Bindless(const vkt::Context& context)
        : physical_(context.physical), device_(context.device) {
        const vkt::Gpu gpu = context.gpu();
        const auto grid = uint32_t(context.options.integer("--grid"));
        const auto texture_count = uint32_t(context.options.integer("--textures"));
        loop_ = context.options.text("--draw") == "loop";
        benchmark_ = context.options.benchmark;

        // The scene (scene.hpp): a floor, then grid x grid objects, each with a
        // random mesh, two random textures (slots 1..texture_count), a turn, a size.
        const Scene scene = make_scene(grid, texture_count);
        half_width_ = scene.half_width;
        const std::vector<Object>& objects = scene.objects;

        // [indirect-commands]
        // One command per object, as vkCmdDrawIndexedIndirect reads them:
        // which mesh (firstIndex, indexCount, vertexOffset), one instance,
        // and firstInstance = the object's index, which the vertex shader
        // sees as gl_InstanceIndex. A non-zero firstInstance in an indirect
        // command needs the feature drawIndirectFirstInstance.
        for (uint32_t i = 0; i < objects.size(); ++i) {
            const Mesh& mesh = scene.meshes[scene.mesh_of[i]];
            draws_.push_back({
                .indexCount = mesh.index_count,
                .instanceCount = 1,
                .firstIndex = mesh.first_index,
                .vertexOffset = mesh.vertex_offset,
                .firstInstance = i,
            });
        }
        if (draws_.size() > context.properties.limits.maxDrawIndirectCount)
            throw vkt::Error(
                "this device draws at most " +
                std::to_string(context.properties.limits.maxDrawIndirectCount) +
                " commands in one indirect draw (maxDrawIndirectCount); use a smaller --grid");
        indirect_ = vkt::create_device_buffer(gpu, draws_.data(),
                                              draws_.size() * sizeof(VkDrawIndexedIndirectCommand),
                                              VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
        // [/indirect-commands]
        index_buffer_ = vkt::create_device_buffer(gpu, scene.indices.data(),
                                                  scene.indices.size() * sizeof(uint16_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        vertex_buffer_ = ch15::create_address_buffer(
            gpu, scene.vertices.data(), scene.vertices.size() * sizeof(Vertex), vertex_address_);
        object_buffer_ = ch15::create_address_buffer(
            gpu, objects.data(), objects.size() * sizeof(Object), object_address_);

        // The textures: slot 0 the grey checker, slots 1.. the procedural ones.
        // (create_texture gives each its own sampler; the set uses one shared.)
        textures_.push_back(vkt::create_texture(gpu, grey_checker(), true, 0.0f));
        for (uint32_t i = 0; i < texture_count; ++i)
            textures_.push_back(
                vkt::create_texture(gpu, vkt::procedural_texture(i, 64), true, 0.0f));
        sampler_ = vkt::create_sampler(device_, 0.0f);
        const auto slot_count = uint32_t(textures_.size());

        // Chapter 07's helpers (vkt/resources/descriptors.hpp) take no flags
        // and no pNext; this set's flags are the lesson, so it is written out.
        // [set-layout]
        // Binding 0: one sampler, immutable (baked into the layout).
        // Binding 1: up to kMaxTextures sampled images, with four flags:
        //  PARTIALLY_BOUND: slots may stay unwritten as long as no shader
        //    actually reads them (without it, every slot must hold a valid
        //    image whenever the set is used in a draw);
        //  VARIABLE_DESCRIPTOR_COUNT: kMaxTextures is only the upper bound;
        //    each set says at allocation how many it really has (only the
        //    binding with the highest number may have it);
        //  UPDATE_AFTER_BIND: writing a slot after the set was bound in a
        //    command buffer does not invalidate that command buffer (without
        //    it, any write does); the draw sees what the set holds at submit;
        //  UPDATE_UNUSED_WHILE_PENDING: slots that a submitted, unfinished
        //    command buffer does not read may be written meanwhile (without
        //    it, the set must not change until every such frame is done).
        const VkDescriptorBindingFlags binding_flags[] = {
            0,
            VK_DESCRIPTOR_BINDING_PARTIALLY_BOUND_BIT |
                VK_DESCRIPTOR_BINDING_VARIABLE_DESCRIPTOR_COUNT_BIT |
                VK_DESCRIPTOR_BINDING_UPDATE_AFTER_BIND_BIT |
                VK_DESCRIPTOR_BINDING_UPDATE_UNUSED_WHILE_PENDING_BIT,
        };
        const VkDescriptorSetLayoutBindingFlagsCreateInfo flags_info{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO,
            .bindingCount = 2,
            .pBindingFlags = binding_flags,
        };
        const VkSampler immutable_sampler = sampler_;
        const VkDescriptorSetLayoutBinding bindings[] = {
            {.binding = 0,
             .descriptorType = VK_DESCRIPTOR_TYPE_SAMPLER,
             .descriptorCount = 1,
             .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT,
             .pImmutableSamplers = &immutable_sampler},
            {.binding = 1,
             .descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
             .descriptorCount = kMaxTextures,
             .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT},
        };
        // A layout with an UPDATE_AFTER_BIND binding must say so as a whole,
        // and its sets must come from a pool created for it (below).
        const VkDescriptorSetLayoutCreateInfo layout_info{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
            .pNext = &flags_info,
            .flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_UPDATE_AFTER_BIND_POOL_BIT,
            .bindingCount = 2,
            .pBindings = bindings,
        };
        VkDescriptorSetLayout set_layout;
        VKT_CHECK(vkCreateDescriptorSetLayout(device_, &layout_info, nullptr, &set_layout));
        set_layout_ = vkt::DescriptorSetLayout(device_, set_layout);
        // [/set-layout]

        // [pool-and-set]
        // The pool holds exactly what the one set uses: slot_count images,
        // not kMaxTextures. The variable count is given at allocation.
        const VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_SAMPLER, 1},
            {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, slot_count},
        };
        const VkDescriptorPoolCreateInfo pool_info{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
            .flags = VK_DESCRIPTOR_POOL_CREATE_UPDATE_AFTER_BIND_BIT,
            .maxSets = 1,
            .poolSizeCount = 2,
            .pPoolSizes = sizes,
        };
        VkDescriptorPool pool;
        VKT_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool));
        pool_ = vkt::DescriptorPool(device_, pool);
        const VkDescriptorSetVariableDescriptorCountAllocateInfo count_info{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_VARIABLE_DESCRIPTOR_COUNT_ALLOCATE_INFO,
            .descriptorSetCount = 1,
            .pDescriptorCounts = &slot_count,
        };
        const VkDescriptorSetAllocateInfo allocate{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
            .pNext = &count_info,
            .descriptorPool = pool_,
            .descriptorSetCount = 1,
            .pSetLayouts = &set_layout,
        };
        VKT_CHECK(vkAllocateDescriptorSets(device_, &allocate, &set_));
        // Only slot 0 now; the rest arrive while frames are drawn (record()).
        write_textures(0, 1);
        // [/pool-and-set]

        // The pipeline from the helpers of chapters 04-08: nothing new in it.
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                       sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(device_, {&set_layout, 1}, {&push, 1});
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "bindless.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "bindless.frag");
        depth_format_ = vkt::choose_depth_format(physical_);
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, context.extent);
        // No vertex bindings or attributes: the vertex shader pulls its own.
        pipeline_ =
            vkt::create_graphics_pipeline(device_, {
                                                       .vertex = vertex,
                                                       .fragment = fragment,
                                                       .layout = layout_,
                                                       .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                       .color_formats = {context.color_format},
                                                       .depth_format = depth_format_,
                                                   });

        std::fprintf(
            stderr,
            "15_bindless: %zu objects (%u x %u and the floor), %u texture slots "
            "(%u textures and the loading one), %s\n",
            objects.size(), grid, grid, slot_count, texture_count,
            loop_ ? "one vkCmdDrawIndexed per object" : "one vkCmdDrawIndexedIndirect for all");
    }

    ~Bindless() override {
        if (record_ms_.empty()) return;
        const vkt::Summary cpu = vkt::summarize(record_ms_);
        std::fprintf(stderr,
                     "15_bindless: recording the draws took %.4f ms median, %.4f ms p95 on the CPU "
                     "(%zu frames)\n",
                     cpu.median, cpu.p95, record_ms_.size());
    }

    void resize(VkExtent2D extent) override {
        depth_ = vkt::create_depth_image(physical_, device_, depth_format_, extent);
    }

    void record(const vkt::Frame& frame) override {
        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        const float angle = 0.6f + 0.05f * float(frame.time), r = 0.75f * half_width_;
        const glm::mat4 view =
            glm::lookAt(glm::vec3(r * std::sin(angle), 0.3f * half_width_, r * std::cos(angle)),
                        glm::vec3(0.0f), glm::vec3(0, 1, 0));
        const glm::mat4 view_projection =
            vkt::vulkan_perspective(glm::radians(50.0f), aspect, 0.1f, 4.0f * half_width_) * view;

        vkt::begin_depth_frame(frame.cmd, depth_.image);
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.30f, 0.45f, 0.65f, 1.0f}}, depth_.view);
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0,
                                nullptr);

        // [stream]
        // The set is bound above, and frames before this one may still be
        // running with it. A few more textures become resident now: writing
        // their slots is allowed because the binding is UPDATE_AFTER_BIND
        // (this command buffer sees the new slots when it is submitted) and
        // UPDATE_UNUSED_WHILE_PENDING (the frames in flight never read these
        // slots: their resident count was lower, so they drew slot 0 there).
        const auto slot_count = uint32_t(textures_.size());
        if (resident_ < slot_count)
            write_textures(resident_, std::min(slot_count, resident_ + kTexturesPerFrame));
        // [/stream]

        const Push push{view_projection, vertex_address_, object_address_, resident_, 0};
        vkCmdPushConstants(frame.cmd, layout_,
                           VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                           sizeof(Push), &push);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        {
            auto scope = frame.gpu_scope("draw");
            const auto start = std::chrono::steady_clock::now();
            // [draw]
            if (!loop_) {
                // Every object in one call: the device reads draws_.size()
                // commands from the buffer, one after another (drawCount > 1
                // needs the feature multiDrawIndirect).
                vkCmdDrawIndexedIndirect(frame.cmd, indirect_.buffer, 0, uint32_t(draws_.size()),
                                         sizeof(VkDrawIndexedIndirectCommand));
            } else {
                // The same draws, one call each.
                for (const VkDrawIndexedIndirectCommand& d : draws_)
                    vkCmdDrawIndexed(frame.cmd, d.indexCount, d.instanceCount, d.firstIndex,
                                     d.vertexOffset, d.firstInstance);
            }
            // [/draw]
            // --benchmark: the CPU's side, the time to record these commands.
            if (benchmark_)
                record_ms_.push_back(std::chrono::duration<double, std::milli>(
                                         std::chrono::steady_clock::now() - start)
                                         .count());
        }
        vkCmdEndRendering(frame.cmd);
    }

private:
    // [write-textures]
    // Points slots [first, end) of binding 1 at their textures' images (the
    // sampler is the immutable one), and counts them as resident.
    void write_textures(uint32_t first, uint32_t end) {
        std::vector<VkDescriptorImageInfo> images;
        for (uint32_t i = first; i < end; ++i)
            images.push_back({.imageView = textures_[i].image.view,
                              .imageLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        const VkWriteDescriptorSet write{
            .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
            .dstSet = set_,
            .dstBinding = 1,
            .dstArrayElement = first,
            .descriptorCount = end - first,
            .descriptorType = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE,
            .pImageInfo = images.data(),
        };
        vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
        resident_ = end;
    }
    // [/write-textures]

    VkPhysicalDevice physical_;
    VkDevice device_;
    bool loop_ = false;
    bool benchmark_ = false;
    std::vector<double> record_ms_;  // --benchmark: CPU time to record the draws, per frame
    float half_width_ = 1.0f;
    std::vector<VkDrawIndexedIndirectCommand> draws_;
    vkt::Buffer indirect_;
    vkt::Buffer index_buffer_;
    vkt::Buffer vertex_buffer_;
    vkt::Buffer object_buffer_;
    VkDeviceAddress vertex_address_ = 0;
    VkDeviceAddress object_address_ = 0;
    std::vector<vkt::Texture> textures_;
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with pool_
    uint32_t resident_ = 0;                 // slots 0 .. resident_ - 1 are written
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "15_bindless", .title = "15 - bindless"};
    spec.requirements.features = {
        // Descriptor indexing: the runtime array, nonuniformEXT on it, and the
        // four binding flags of the texture array.
        VKT_FEATURE_12(runtimeDescriptorArray),
        VKT_FEATURE_12(shaderSampledImageArrayNonUniformIndexing),
        VKT_FEATURE_12(descriptorBindingPartiallyBound),
        VKT_FEATURE_12(descriptorBindingVariableDescriptorCount),
        VKT_FEATURE_12(descriptorBindingSampledImageUpdateAfterBind),
        VKT_FEATURE_12(descriptorBindingUpdateUnusedWhilePending),
        // Vertices and objects through GPU addresses.
        VKT_FEATURE_12(bufferDeviceAddress),
        // One indirect call with many draws, each with its own firstInstance.
        VKT_FEATURE_10(multiDrawIndirect),
        VKT_FEATURE_10(drawIndirectFirstInstance),
        // The depth barrier's DEPTH_ATTACHMENT_OPTIMAL layout (chapter 08).
        VKT_FEATURE_12(separateDepthStencilLayouts),
    };
    spec.options = {
        {.name = "--draw",
         .type = vkt::OptionType::choice,
         .help = "one indirect multi-draw, or a loop of one draw per object",
         .default_value = "indirect",
         .choices = {"indirect", "loop"}},
        // 250 x 250 + 1 = 62,501 draws: within the 65,535 that every device
        // with multiDrawIndirect accepts in one call (maxDrawIndirectCount).
        {.name = "--grid",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "objects on an N x N grid",
         .default_value = "32",
         .min = 1,
         .max = 250},
        {.name = "--textures",
         .type = vkt::OptionType::integer,
         .value_name = "N",
         .help = "how many distinct textures",
         .default_value = "48",
         .min = 1,
         .max = 96},
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Bindless>(context);
    });
}
