// Chapter 08: depth.
//
// Five objects that cross each other: chapter 07's two cubes, a bar through
// the big cube, a tilted cube cutting into it and one further back. Drawing
// order no longer decides what is seen: a depth attachment keeps, for every
// pixel, the depth of the nearest surface drawn so far, and the depth test
// drops every fragment behind it. New here: choosing a depth format the
// device supports, the depth image and its per-frame barrier, the depth
// attachment in vkCmdBeginRendering, and a perspective camera whose depth
// runs from 0 at the near plane to 1 at the far plane. Descriptors come from
// chapter 07's helpers (vkt/resources/descriptors.hpp).

#include "uniforms.hpp"
#include "vkt/core/barrier.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/align.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/coloured_cube.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

using ch08::FrameUniforms;
using ch08::ObjectUniforms;

// Chapter 07's cube: edge 1, a colour per face (vkt/scene/coloured_cube.hpp).
using Vertex = vkt::shapes::ColouredVertex;

// [choose-format]
// The depth formats, best first. D32_SFLOAT: 32-bit float depth, the most
// precision and no stencil we would not use. Then the same with 8 bits of
// stencil, then 24-bit fixed point with stencil, then D16_UNORM, which every
// device must support as a depth attachment (the others are optional).
VkFormat choose_depth_format(VkPhysicalDevice physical) {
    const VkFormat candidates[] = {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D32_SFLOAT_S8_UINT,
                                   VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM};
    for (VkFormat format : candidates) {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(physical, format, &properties);
        // Our depth image is optimally tiled: only optimalTilingFeatures count.
        if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
            return format;
    }
    throw vkt::Error(
        "no depth format can be a depth attachment on this device (tried "
        "D32_SFLOAT, D32_SFLOAT_S8_UINT, D24_UNORM_S8_UINT, D16_UNORM)");
}
// [/choose-format]

const char* format_name(VkFormat format) {
    switch (format) {
        case VK_FORMAT_D32_SFLOAT:
            return "VK_FORMAT_D32_SFLOAT";
        case VK_FORMAT_D32_SFLOAT_S8_UINT:
            return "VK_FORMAT_D32_SFLOAT_S8_UINT";
        case VK_FORMAT_D24_UNORM_S8_UINT:
            return "VK_FORMAT_D24_UNORM_S8_UINT";
        default:
            return "VK_FORMAT_D16_UNORM";
    }
}

constexpr uint32_t object_count = 5;

// [scene]
// Object transforms are T * R * S: scale the unit cube into shape, turn it,
// then move it into place (glm's calls multiply on the right, so the call
// written first is applied last).
glm::mat4 trs(glm::vec3 position, float angle, glm::vec3 axis, glm::vec3 size) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, angle, glm::normalize(axis));
    return glm::scale(m, size);
}

std::array<ObjectUniforms, object_count> scene(double t) {
    const float time = float(t);
    const glm::vec3 up(0.0f, 1.0f, 0.0f), white(1.0f), dark(0.0f);
    const float orbit = 1.2f + 0.9f * time;
    const glm::vec3 small_at = 2.2f * glm::vec3(std::sin(orbit), 0.0f, std::cos(orbit));
    return {{
        // 07's big cube (edge 2) and small orbiting cube (edge 0.4).
        {trs({0, 0, 0}, 0.5f + 0.6f * time, up, glm::vec3(2.0f)), white, 0.0f},
        {trs(small_at, -2.0f * time, up, glm::vec3(0.4f)), white, 0.5f},
        // A bar through the big cube, sticking out of both sides, darker.
        {trs({0, -0.3f, 0}, 0.3f + 0.3f * time, {0.2f, 1, 0}, {4.4f, 0.35f, 0.35f}), dark, 0.35f},
        // A tilted cube cutting into the big cube's left corner, orange.
        {trs({-1.3f, 0.7f, 0.3f}, 0.8f, {1, 1, 0}, glm::vec3(1.1f)), {1, 0.5f, 0}, 0.45f},
        // A cube further back, half hidden, bluish.
        {trs({2.3f, 0.4f, -3.0f}, 0.3f * time, up, glm::vec3(1.6f)), {0.3f, 0.3f, 1}, 0.4f},
    }};
}
// [/scene]

// [camera]
// The camera at (0, 2, 5.5) looks at the origin. glm::perspective, with the
// build's GLM_FORCE_DEPTH_ZERO_TO_ONE, maps depth to Vulkan's 0..1; negating
// proj[1][1] turns world up into framebuffer up (Vulkan's y points down).
// vkt::vulkan_perspective (vkt/scene/camera_math.hpp) is this, for later chapters.
FrameUniforms camera(VkExtent2D extent) {
    FrameUniforms frame;
    frame.view = glm::lookAt(glm::vec3(0.0f, 2.0f, 5.5f), glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const float aspect = float(extent.width) / float(extent.height);
    frame.proj = glm::perspective(glm::radians(45.0f), aspect, 0.1f, 100.0f);
    frame.proj[1][1] = -frame.proj[1][1];
    return frame;
}
// [/camera]

class Scene : public vkt::Renderer {
public:
    explicit Scene(const vkt::Context& context)
        : physical_(context.physical), device_(context.device) {
        // [depth-image]
        // Chosen once; the image has the colour target's size, so resize()
        // makes a new one. Only the depth tests touch it: DEPTH_STENCIL_ATTACHMENT
        // is its only usage, and its contents never leave the GPU.
        depth_format_ = choose_depth_format(physical_);
        std::fprintf(stderr, "08_depth: depth format: %s\n", format_name(depth_format_));
        depth_ = vkt::create_image_2d(physical_, device_, depth_format_, context.extent,
                                      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                      VK_IMAGE_ASPECT_DEPTH_BIT);
        // [/depth-image]

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

        // Chapter 07's descriptors, with its helpers: per frame in flight, a
        // camera buffer (binding 0) and the objects' blocks (binding 1, dynamic).
        stride_ = vkt::align_up(sizeof(ObjectUniforms),
                                context.properties.limits.minUniformBufferOffsetAlignment);
        const VkDescriptorSetLayoutBinding bindings[] = {
            {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
            {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        };
        set_layout_ = vkt::create_descriptor_set_layout(device_, bindings);
        const uint32_t sets = context.frames_in_flight;
        const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, sets},
                                              {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, sets}};
        pool_ = vkt::create_descriptor_pool(device_, sets, sizes);
        for (uint32_t i = 0; i < sets; ++i) {
            frame_buffers_.push_back(vkt::create_host_buffer(gpu, sizeof(FrameUniforms),
                                                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            object_buffers_.push_back(vkt::create_host_buffer(gpu, object_count * stride_,
                                                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
            sets_.push_back(vkt::allocate_descriptor_set(device_, pool_, set_layout_));
            vkt::write_buffer_descriptor(device_, sets_[i], 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                         frame_buffers_[i].buffer, 0, sizeof(FrameUniforms));
            vkt::write_buffer_descriptor(device_, sets_[i], 1,
                                         VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                                         object_buffers_[i].buffer, 0, sizeof(ObjectUniforms));
        }

        // [pipeline]
        // depth_format turns on the depth test (compare LESS: a fragment
        // survives if it is nearer than what the pixel holds) and depth writes.
        const VkDescriptorSetLayout set_layouts[] = {set_layout_};
        layout_ = vkt::create_pipeline_layout(device_, set_layouts);
        vkt::ShaderModule vertex = vkt::load_shader(device_, context.chapter, "scene.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device_, context.chapter, "scene.frag");
        VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attributes[] = {
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
                                                       .depth_write = true,
                                                       .depth_compare = VK_COMPARE_OP_LESS,
                                                   });
        // [/pipeline]
    }

    // [resize]
    void resize(VkExtent2D extent) override {
        // The GPU is idle here (the runner waited), so the old image can go.
        depth_ = vkt::create_image_2d(physical_, device_, depth_format_, extent,
                                      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                      VK_IMAGE_ASPECT_DEPTH_BIT);
    }
    // [/resize]

    void record(const vkt::Frame& frame) override {
        const FrameUniforms camera_block = camera(frame.extent);
        std::memcpy(frame_buffers_[frame.slot].mapped, &camera_block, sizeof camera_block);
        const auto objects = scene(frame.time);
        auto* object_bytes = static_cast<std::byte*>(object_buffers_[frame.slot].mapped);
        for (uint32_t i = 0; i < object_count; ++i)
            std::memcpy(object_bytes + i * stride_, &objects[i], sizeof(ObjectUniforms));

        // [depth-barrier]
        // One depth image serves every frame in flight. Before this frame
        // clears it, the previous frame's depth tests must be done with it:
        // wait for their writes (EARLY and LATE fragment tests) before the
        // layout change, and make the new layout ready for this frame's tests.
        // UNDEFINED: the old contents are not needed (we clear).
        constexpr VkPipelineStageFlags2 tests = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        vkt::image_barrier(frame.cmd, depth_.image, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, tests,
                           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, tests,
                           VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                           VK_IMAGE_ASPECT_DEPTH_BIT);
        // [/depth-barrier]

        // [begin-rendering]
        VkRenderingAttachmentInfo colour{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = frame.target_view,
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.02f, 0.02f, 0.04f, 1.0f}}},
        };
        // Cleared to 1.0, the far plane: every first fragment is nearer.
        // Nothing reads depth after the frame, so it need not be stored.
        VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = depth_.view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
            .clearValue = {.depthStencil = {1.0f, 0}},
        };
        VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .renderArea = {{0, 0}, frame.extent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &colour,
            .pDepthAttachment = &depth,
        };
        vkCmdBeginRendering(frame.cmd, &rendering);
        // [/begin-rendering]

        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        const VkBuffer vertex_buffer = vertex_buffer_.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, &vertex_buffer, &offset);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        for (uint32_t i = 0; i < object_count; ++i) {
            const uint32_t dynamic_offset = uint32_t(i * stride_);
            vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1,
                                    &sets_[frame.slot], 1, &dynamic_offset);
            vkCmdDrawIndexed(frame.cmd, index_count_, 1, 0, 0, 0);
        }
        vkCmdEndRendering(frame.cmd);
    }

private:
    VkPhysicalDevice physical_;
    VkDevice device_;
    VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
    vkt::Image depth_;
    uint32_t index_count_ = 0;
    VkDeviceSize stride_ = 0;
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    std::vector<vkt::Buffer> frame_buffers_;
    std::vector<vkt::Buffer> object_buffers_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    std::vector<VkDescriptorSet> sets_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    vkt::ChapterSpec spec{.name = "08_depth", .title = "08 - depth"};
    // DEPTH_ATTACHMENT_OPTIMAL, a layout for the depth aspect alone, is only
    // allowed with this Vulkan 1.2 feature turned on (every 1.3 device has it).
    spec.requirements.features = {VKT_FEATURE_12(separateDepthStencilLayouts)};
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Scene>(context);
    });
}
