// Chapter 06: push constants.
//
// Twelve objects, one pipeline: a 4x3 grid of shapes (triangles, squares,
// pentagons and hexagons, all in one vertex buffer and one index buffer), each
// turning at its own speed in its own colour. What differs from one draw to
// the next, a transform and a colour, travels in push constants: a few bytes
// recorded straight into the command buffer with vkCmdPushConstants, no
// buffer, no descriptor. The buffers themselves come from chapter 05's
// vkt::create_device_buffer.

#include "vkt/frame/runner.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace {

// Chapter 05's vertex: a position and a colour, here a grey shade.
struct Vertex {
    glm::vec2 position;
    glm::vec3 shade;
};
static_assert(sizeof(Vertex) == 20 && offsetof(Vertex, shade) == 8);

// [push-struct]
// The C++ mirror of the shader's push_constant block (std430 layout). glm's
// types have the sizes GLSL's have (a mat2 is two vec2 columns, 8 bytes
// apart), and with the members in this order no padding is needed; the
// static_asserts make sure of every offset the shader assumes.
struct PushConstants {
    glm::vec4 colour;     // offset 0
    glm::mat2 transform;  // offset 16: column 0 at 16, column 1 at 24
    glm::vec2 offset;     // offset 32
};
static_assert(offsetof(PushConstants, colour) == 0);
static_assert(offsetof(PushConstants, transform) == 16);
static_assert(offsetof(PushConstants, offset) == 32);
static_assert(sizeof(PushConstants) == 40);
static_assert(sizeof(PushConstants) <= 128, "128 bytes is all that every device must offer");
// [/push-struct]

// [meshes]
// Which part of the shared index buffer draws a shape, and where its vertices
// start in the shared vertex buffer.
struct Mesh {
    uint32_t first_index;
    uint32_t index_count;
    int32_t vertex_offset;  // added to every index of the mesh
};

// Regular polygons of 3 to 6 corners, radius 1, a corner at the top (y is
// down): a white centre vertex and a fan of grey rim vertices. Every shape's
// indices count from its own centre vertex, 0, as if it were alone;
// vertex_offset moves them to where its vertices really are.
std::array<Mesh, 4> make_shapes(std::vector<Vertex>& vertices, std::vector<uint16_t>& indices) {
    std::array<Mesh, 4> meshes;
    for (uint32_t shape = 0; shape < 4; ++shape) {
        const uint32_t corners = shape + 3;
        meshes[shape] = {uint32_t(indices.size()), 3 * corners, int32_t(vertices.size())};
        vertices.push_back({{0.0f, 0.0f}, glm::vec3(1.0f)});
        for (uint32_t k = 0; k < corners; ++k) {
            const float angle = float(k) * 6.2831853f / float(corners);
            vertices.push_back({{std::sin(angle), -std::cos(angle)}, glm::vec3(0.45f)});
            indices.insert(indices.end(), {0, uint16_t(1 + k), uint16_t(1 + (k + 1) % corners)});
        }
    }
    return meshes;
}
// [/meshes]

// [objects]
// Object i of 12: its grid cell (4 columns, 3 rows), its shape, its colour and
// its turning. Everything is a function of i and the frame's time, so a
// headless run draws the same picture every time.
constexpr uint32_t columns = 4, rows = 3;

PushConstants object_constants(uint32_t i, double time, VkExtent2D extent) {
    const uint32_t column = i % columns, row = i / columns;
    // A hue around the colour wheel, softened towards white: (1, 0.25, 0.25)
    // for object 0, then every 30 degrees of hue.
    const glm::vec3 hue = glm::clamp(
        glm::abs(glm::mod(float(i) / 2.0f + glm::vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f,
        1.0f);
    const glm::vec3 colour = 0.25f + 0.75f * hue;
    // Start turned by 0.4 rad per object, then turn at 0.5 to 2.7 rad/s,
    // every other one the other way.
    const float speed = (0.5f + 0.2f * float(i)) * (i % 2 ? -1.0f : 1.0f);
    const float angle = 0.4f * float(i) + speed * float(time);
    const float c = std::cos(angle), s = std::sin(angle);
    // Rotate, scale to radius 0.28 (of half the image's height), and divide x
    // by the aspect ratio so that shapes stay regular in any window.
    const float scale = 0.28f, aspect = float(extent.width) / float(extent.height);
    const glm::mat2 rotation(c, s, -s, c);  // columns: where x and y go
    const glm::mat2 fit(scale / aspect, 0.0f, 0.0f, scale);
    return {
        .colour = glm::vec4(colour, 1.0f),
        .transform = fit * rotation,
        .offset = {-0.75f + 0.5f * float(column), -2.0f / 3.0f + 2.0f / 3.0f * float(row)},
    };
}
// [/objects]

class Shapes : public vkt::Renderer {
public:
    explicit Shapes(const vkt::Context& context) {
        VkDevice device = context.device;

        // [limit]
        // Vulkan promises at least 128 bytes of push constants; a device may
        // offer more (lavapipe and many GPUs offer 256). Say so clearly
        // rather than fail in pipeline creation.
        const uint32_t limit = context.properties.limits.maxPushConstantsSize;
        if (limit < sizeof(PushConstants))
            throw vkt::Error("this device offers " + std::to_string(limit) +
                             " bytes of push constants; chapter 06 needs " +
                             std::to_string(sizeof(PushConstants)));
        // [/limit]

        // [buffers]
        std::vector<Vertex> vertices;
        std::vector<uint16_t> indices;
        meshes_ = make_shapes(vertices, indices);
        const vkt::Gpu gpu = context.gpu();
        vertex_buffer_ =
            vkt::create_device_buffer(gpu, vertices.data(), vertices.size() * sizeof(Vertex),
                                      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ =
            vkt::create_device_buffer(gpu, indices.data(), indices.size() * sizeof(uint16_t),
                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        // [/buffers]

        // [layout]
        // One range of push constants, bytes 0 to 40, that both shaders see.
        VkPushConstantRange range{
            .stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
            .offset = 0,
            .size = sizeof(PushConstants),
        };
        layout_ = vkt::create_pipeline_layout(device, {}, {&range, 1});
        // [/layout]

        vkt::ShaderModule vertex = vkt::load_shader(device, context.chapter, "shapes.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device, context.chapter, "shapes.frag");
        VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
        VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(Vertex, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, shade)},
        };
        pipeline_ =
            vkt::create_graphics_pipeline(device, {
                                                      .vertex = vertex,
                                                      .fragment = fragment,
                                                      .layout = layout_,
                                                      .bindings = {&binding, 1},
                                                      .attributes = attributes,
                                                      .color_formats = {context.color_format},
                                                  });
    }

    void record(const vkt::Frame& frame) override {
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.02f, 0.02f, 0.04f, 1.0f}});

        // [draw]
        // Bound once for all twelve draws: the pipeline and both buffers.
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        VkBuffer vertex_buffers[] = {vertex_buffer_.buffer};
        VkDeviceSize offsets[] = {0};
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, vertex_buffers, offsets);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);

        // Per object: 40 bytes of push constants, then its part of the
        // index buffer. The values are copied into the command buffer right
        // here, so `constants` may change for the next draw at once.
        for (uint32_t i = 0; i < columns * rows; ++i) {
            const PushConstants constants = object_constants(i, frame.time, frame.extent);
            vkCmdPushConstants(frame.cmd, layout_,
                               VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(constants), &constants);
            const Mesh& mesh = meshes_[(i % columns + i / columns) % meshes_.size()];
            vkCmdDrawIndexed(frame.cmd, mesh.index_count, 1, mesh.first_index, mesh.vertex_offset,
                             0);
        }
        // [/draw]
        vkCmdEndRendering(frame.cmd);
    }

private:
    std::array<Mesh, 4> meshes_{};
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    return vkt::run_chapter(
        argc, argv, {.name = "06_push_constants", .title = "06 - push constants"},
        [](const vkt::Context& context) { return std::make_unique<Shapes>(context); });
}
