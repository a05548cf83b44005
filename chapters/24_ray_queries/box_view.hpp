#pragma once
// Chapter 24's --view boxes: the boxes a top level can take from its bottom
// levels, drawn as lines over the scene. Orange: each bottom level's bounds,
// its mesh's box in object space, carried into the world by the instance's
// transform (a turned box for the turned torus). Blue: the axis-aligned box
// in the world around those eight corners, the box an instance gets from its
// bottom level's box alone; a driver may fit a tighter one (round the turned
// vertices, say). A ray that misses the instance's box skips the whole mesh.
// The boxes inside each level, and how the top level groups the instances,
// are the driver's own and cannot be read.

#include "vkt/core/check.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"
#include "vkt/scene/meshes.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

namespace ch24 {

class BoxView {
public:
    struct Line {
        glm::vec3 position;
        glm::vec3 colour;
    };
    static constexpr uint32_t lines_per_object = 2 * 12;  // two boxes of twelve edges

    BoxView(const vkt::Gpu& gpu, const std::string& chapter, VkFormat color_format,
            VkFormat depth_format, uint32_t frames_in_flight, uint32_t objects,
            const vkt::shapes::MeshBuilder& meshes, std::span<const vkt::shapes::MeshRange> ranges)
        : objects_(objects) {
        // Each mesh's box in its own space, from the vertices its indices use.
        for (const vkt::shapes::MeshRange& range : ranges) {
            glm::vec3 low(1e30f), high(-1e30f);
            for (uint32_t i = 0; i < range.index_count; ++i) {
                const glm::vec3 p = meshes.vertices[meshes.indices[range.first_index + i]].position;
                low = glm::min(low, p);
                high = glm::max(high, p);
            }
            bounds_.push_back({low, high});
        }
        for (uint32_t slot = 0; slot < frames_in_flight; ++slot)
            buffers_.push_back(vkt::create_host_buffer(
                gpu, VkDeviceSize(objects) * lines_per_object * 2 * sizeof(Line),
                VK_BUFFER_USAGE_VERTEX_BUFFER_BIT));
        const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
        layout_ = vkt::create_pipeline_layout(gpu.device, {}, {&push, 1});
        const vkt::ShaderModule vertex = vkt::load_shader(gpu.device, chapter, "boxes.vert");
        const vkt::ShaderModule fragment = vkt::load_shader(gpu.device, chapter, "boxes.frag");
        const VkVertexInputBindingDescription binding{0, sizeof(Line), VK_VERTEX_INPUT_RATE_VERTEX};
        const VkVertexInputAttributeDescription attributes[] = {
            {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Line, position)},
            {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Line, colour)},
        };
        // Lines, tested against the scene's depth (a box's far edges hide
        // behind what it holds) but not written into it.
        pipeline_ = vkt::create_graphics_pipeline(gpu.device,
                                                  {.vertex = vertex,
                                                   .fragment = fragment,
                                                   .layout = layout_,
                                                   .bindings = {&binding, 1},
                                                   .attributes = attributes,
                                                   .topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST,
                                                   .color_formats = {color_format},
                                                   .depth_format = depth_format,
                                                   .depth_write = false,
                                                   .depth_compare = VK_COMPARE_OP_LESS_OR_EQUAL});
    }

    // Inside the lit pass's rendering, after the scene. The slot's buffer is
    // free: the runner waited for the slot's fence before record().
    void record(VkCommandBuffer cmd, uint32_t slot, const glm::mat4& clip_from_world,
                std::span<const glm::mat4> world_from_object, std::span<const uint32_t> mesh) {
        // Written straight into the slot's mapped buffer: no copy per frame.
        Line* const first = static_cast<Line*>(buffers_[slot].mapped);
        Line* line = first;
        for (size_t o = 0; o < world_from_object.size() && o < objects_; ++o) {
            // [boxes]
            const Bounds& b = bounds_[mesh[o]];
            std::array<glm::vec3, 8> corners;
            glm::vec3 low(1e30f), high(-1e30f);
            for (uint32_t c = 0; c < 8; ++c) {
                const glm::vec3 local{c & 1 ? b.high.x : b.low.x, c & 2 ? b.high.y : b.low.y,
                                      c & 4 ? b.high.z : b.low.z};
                corners[c] = glm::vec3(world_from_object[o] * glm::vec4(local, 1.0f));
                low = glm::min(low, corners[c]);
                high = glm::max(high, corners[c]);
            }
            line = add_box(line, corners, {1.0f, 0.55f, 0.1f});
            std::array<glm::vec3, 8> aligned;
            for (uint32_t c = 0; c < 8; ++c)
                aligned[c] = {c & 1 ? high.x : low.x, c & 2 ? high.y : low.y,
                              c & 4 ? high.z : low.z};
            line = add_box(line, aligned, {0.15f, 0.3f, 1.0f});
            // [/boxes]
        }
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        const VkBuffer buffer = buffers_[slot].buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &clip_from_world);
        vkCmdDraw(cmd, uint32_t(line - first), 1, 0, 0);
    }

private:
    struct Bounds {
        glm::vec3 low, high;
    };

    // The twelve edges of a box whose corner c has bit 0 for x, 1 for y, 2
    // for z: every pair of corners that differ in one bit.
    static Line* add_box(Line* line, const std::array<glm::vec3, 8>& corner, glm::vec3 colour) {
        for (uint32_t c = 0; c < 8; ++c)
            for (uint32_t bit : {1u, 2u, 4u})
                if (!(c & bit)) {
                    *line++ = {corner[c], colour};
                    *line++ = {corner[c | bit], colour};
                }
        return line;
    }

    uint32_t objects_;
    std::vector<Bounds> bounds_;        // per mesh, in its own space
    std::vector<vkt::Buffer> buffers_;  // per frame slot, host-visible
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace ch24
