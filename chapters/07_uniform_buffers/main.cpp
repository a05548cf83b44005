// Chapter 07: uniform buffers and descriptor sets.
//
// Two cubes: a big one turning about its own up axis, and a small one, a fifth
// of its size, orbiting it and turning the other way. The camera (view and
// projection) lives in a uniform buffer written once per frame; each cube's
// world matrix lives in a dynamic uniform buffer, one block per cube, and each
// draw picks its block with a dynamic offset. The shaders find both buffers
// through a descriptor set: its layout, the pool it comes from, and the
// writes that point it at the buffers are all written out here.
//
// There is no depth buffer yet (chapter 08): back-face culling alone makes a
// single convex cube look right, but whichever cube is drawn last covers the
// other, even when it is behind it.

#include "uniforms.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/align.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/coloured_cube.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cstring>
#include <vector>

namespace {

using ch07::FrameUniforms;
using ch07::ObjectUniforms;

// The cube of edge 1 with a colour per face: vkt/scene/coloured_cube.hpp.
using Vertex = vkt::shapes::ColouredVertex;

constexpr uint32_t object_count = 2;

// [scene]
// Everything is a function of the frame's time, so a headless run draws the
// same picture every time. The big cube (edge 2) turns at 0.6 rad/s; the small
// one (edge 0.4) orbits at radius 2.2, 0.9 rad/s, and turns at -2 rad/s,
// tinted half-way to white so that it stands out.
std::array<ObjectUniforms, object_count> scene(double t) {
    const float time = float(t);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::mat4 big =
        glm::scale(glm::rotate(glm::mat4(1.0f), 0.5f + 0.6f * time, up), glm::vec3(2.0f));
    const float orbit = 1.2f + 0.9f * time;
    glm::mat4 small =
        glm::translate(glm::mat4(1.0f), 2.2f * glm::vec3(std::sin(orbit), 0.0f, std::cos(orbit)));
    small = glm::scale(glm::rotate(small, -2.0f * time, up), glm::vec3(0.4f));
    return {{
        {.world = big, .tint = glm::vec3(1.0f), .tint_amount = 0.0f},
        {.world = small, .tint = glm::vec3(1.0f), .tint_amount = 0.5f},
    }};
}

FrameUniforms camera(VkExtent2D extent) {
    FrameUniforms frame;
    frame.view = glm::lookAt(glm::vec3(0.0f, 2.0f, 5.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    // A perspective projection for Vulkan's clip space; chapter 08 derives it.
    frame.proj = glm::perspective(glm::radians(45.0f), float(extent.width) / float(extent.height),
                                  0.1f, 100.0f);
    frame.proj[1][1] = -frame.proj[1][1];
    return frame;
}
// [/scene]

class Cubes : public vkt::Renderer {
public:
    explicit Cubes(const vkt::Context& context) : device_(context.device) {
        std::vector<Vertex> vertices;
        std::vector<uint16_t> indices;
        vkt::shapes::make_coloured_cube(vertices, indices);
        index_count_ = uint32_t(indices.size());
        const vkt::Gpu gpu = context.gpu();
        vertex_buffer_ =
            vkt::create_device_buffer(gpu, vertices.data(), vertices.size() * sizeof(Vertex),
                                      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ =
            vkt::create_device_buffer(gpu, indices.data(), indices.size() * sizeof(uint16_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

        // [stride]
        // Each object's block starts at a multiple of the device's
        // minUniformBufferOffsetAlignment (a power of two, 256 at most), so
        // the 80-byte blocks sit `stride_` bytes apart.
        const VkDeviceSize alignment = context.properties.limits.minUniformBufferOffsetAlignment;
        stride_ = vkt::align_up(sizeof(ObjectUniforms), alignment);
        // [/stride]

        // [buffers]
        // One camera buffer and one object buffer per frame in flight: while
        // the GPU may still be reading frame N's buffers, the CPU writes frame
        // N+1's into the other set. Host-visible and coherent, mapped for good:
        // a memcpy is all an update takes.
        for (uint32_t i = 0; i < context.frames_in_flight; ++i) {
            frame_buffers_.push_back(vkt::create_host_buffer(gpu, sizeof(FrameUniforms),
                                                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            object_buffers_.push_back(vkt::create_host_buffer(gpu, object_count * stride_,
                                                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
        }
        // [/buffers]

        // [set-layout]
        // What set 0 holds: binding 0, one uniform buffer; binding 1, one
        // dynamic uniform buffer. Only the vertex shader reads them.
        VkDescriptorSetLayoutBinding bindings[] = {
            {
                .binding = 0,
                .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                .descriptorCount = 1,
                .stageFlags = VK_SHADER_STAGE_VERTEX_BIT,
            },
            {
                .binding = 1,
                .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                .descriptorCount = 1,
                .stageFlags = VK_SHADER_STAGE_VERTEX_BIT,
            },
        };
        VkDescriptorSetLayoutCreateInfo layout_info{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
            .bindingCount = 2,
            .pBindings = bindings,
        };
        VkDescriptorSetLayout set_layout;
        VKT_CHECK(vkCreateDescriptorSetLayout(device_, &layout_info, nullptr, &set_layout));
        set_layout_ = vkt::DescriptorSetLayout(device_, set_layout);
        // [/set-layout]

        // [pool]
        // Room for one set per frame in flight, and the descriptors in them.
        const uint32_t sets = context.frames_in_flight;
        VkDescriptorPoolSize sizes[] = {
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets},
            {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, sets},
        };
        VkDescriptorPoolCreateInfo pool_info{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
            .maxSets = sets,
            .poolSizeCount = 2,
            .pPoolSizes = sizes,
        };
        VkDescriptorPool pool;
        VKT_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool));
        pool_ = vkt::DescriptorPool(device_, pool);
        // [/pool]

        // [sets]
        // Allocate the sets, then point each at its frame's two buffers. The
        // dynamic binding covers one object's block; the offset of the block
        // is given per draw.
        std::vector<VkDescriptorSetLayout> layouts(sets, set_layout_);
        sets_.resize(sets);
        VkDescriptorSetAllocateInfo allocate{
            .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
            .descriptorPool = pool_,
            .descriptorSetCount = sets,
            .pSetLayouts = layouts.data(),
        };
        VKT_CHECK(vkAllocateDescriptorSets(device_, &allocate, sets_.data()));
        for (uint32_t i = 0; i < sets; ++i) {
            VkDescriptorBufferInfo frame_info{frame_buffers_[i].buffer, 0, sizeof(FrameUniforms)};
            VkDescriptorBufferInfo object_info{object_buffers_[i].buffer, 0,
                                               sizeof(ObjectUniforms)};
            VkWriteDescriptorSet writes[] = {
                {
                    .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                    .dstSet = sets_[i],
                    .dstBinding = 0,
                    .descriptorCount = 1,
                    .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                    .pBufferInfo = &frame_info,
                },
                {
                    .sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                    .dstSet = sets_[i],
                    .dstBinding = 1,
                    .descriptorCount = 1,
                    .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                    .pBufferInfo = &object_info,
                },
            };
            vkUpdateDescriptorSets(device_, 2, writes, 0, nullptr);
        }
        // [/sets]

        // [pipeline]
        // The pipeline layout names the set layout; back faces are culled, so
        // of each convex cube only the faces turned towards us are drawn.
        VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device_, set_layouts);
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "cube.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "cube.frag");
        VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, colour)},
        };
        pipeline_ = vkt::create_graphics_pipeline(device_,
                                                  {
                                                      .vertex = vertex,
                                                      .fragment = fragment,
                                                      .layout = layout_,
                                                      .bindings = {&binding, 1},
                                                      .attributes = attributes,
                                                      .cull_mode = VK_CULL_MODE_BACK_BIT,
                                                      .front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE,
                                                      .color_formats = {context.color_format},
                                                  });
        // [/pipeline]
    }

    void record(const vkt::Frame& frame) override {
        // [update]
        // The runner waited for this slot's previous frame before calling
        // record(), so the GPU is done with this slot's buffers: overwrite them.
        const FrameUniforms camera_block = camera(frame.extent);
        std::memcpy(frame_buffers_[frame.slot].mapped, &camera_block, sizeof camera_block);
        const auto objects = scene(frame.time);
        auto* object_bytes = static_cast<std::byte*>(object_buffers_[frame.slot].mapped);
        for (uint32_t i = 0; i < object_count; ++i)
            std::memcpy(object_bytes + i * stride_, &objects[i], sizeof(ObjectUniforms));
        // [/update]

        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.02f, 0.02f, 0.04f, 1.0f}});
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);

        // [draw]
        // The same set for both draws, with a different dynamic offset: the
        // first object's block at 0, the second's at stride_. In drawing
        // order: the big cube, then the small one over it.
        for (uint32_t i = 0; i < object_count; ++i) {
            const uint32_t dynamic_offset = uint32_t(i * stride_);
            vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1,
                                    &sets_[frame.slot], 1, &dynamic_offset);
            vkCmdDrawIndexed(frame.cmd, index_count_, 1, 0, 0, 0);
        }
        // [/draw]
        vkCmdEndRendering(frame.cmd);
    }

private:
    VkDevice device_;
    uint32_t index_count_ = 0;
    VkDeviceSize stride_ = 0;
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    std::vector<vkt::Buffer> frame_buffers_;   // [slot]: FrameUniforms
    std::vector<vkt::Buffer> object_buffers_;  // [slot]: object_count blocks, stride_ apart
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;           // owns sets_: they go when it goes
    std::vector<VkDescriptorSet> sets_;  // [slot]
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    return vkt::run_chapter(
        argc, argv, {.name = "07_uniform_buffers", .title = "07 - uniform buffers"},
        [](const vkt::Context& context) { return std::make_unique<Cubes>(context); });
}
