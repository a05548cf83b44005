// Chapter 05: vertex and index buffers.
//
// Chapter 04's triangle lived inside its vertex shader. Here the vertices live
// in a buffer the application fills: a hexagon of seven vertices (a centre and
// six rim corners), each with a position and a colour, and an index buffer
// that says which three vertices make each of its six triangles. Getting them
// into fast device-local memory takes a staging buffer and a copy on the GPU,
// all written out below. From chapter 06 on, vkt::create_buffer,
// vkt::one_time_submit and vkt::create_device_buffer (common/resources/src/upload.cpp)
// do the same in one call each.

#include "vkt/core/owned.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

// [vertex]
// One vertex as the GPU will read it: 2 floats of position, then 3 floats of
// colour, 20 bytes, no padding. The attribute descriptions below repeat these
// numbers to Vulkan, so the compiler checks them here.
struct Vertex {
    glm::vec2 position;  // clip space: x right, y down, -1 to 1
    glm::vec3 colour;    // linear RGB
};
static_assert(sizeof(Vertex) == 20, "the vertex stride the pipeline is told");
static_assert(offsetof(Vertex, position) == 0, "attribute 0's offset");
static_assert(offsetof(Vertex, colour) == 8, "attribute 1's offset");
// [/vertex]

// [hexagon]
// A hexagon with a point at the top, radius 0.75. Its x coordinates are
// squeezed by 3/4 (0.75 * cos 30 deg * 3/4 = 0.4871) so that it is regular in
// a 4:3 image such as the default 800x600; chapter 06 does this properly.
constexpr float rx = 0.4871f, ry = 0.375f, top = 0.75f;
constexpr std::array<Vertex, 7> vertices{{
    {{0.0f, 0.0f}, {0.8f, 0.8f, 0.8f}},  // 0: the centre, a light grey
    {{0.0f, -top}, {1.0f, 0.0f, 0.0f}},  // 1: top, red
    {{rx, -ry}, {1.0f, 1.0f, 0.0f}},     // 2: upper right, yellow
    {{rx, ry}, {0.0f, 1.0f, 0.0f}},      // 3: lower right, green
    {{0.0f, top}, {0.0f, 1.0f, 1.0f}},   // 4: bottom, cyan
    {{-rx, ry}, {0.0f, 0.0f, 1.0f}},     // 5: lower left, blue
    {{-rx, -ry}, {1.0f, 0.0f, 1.0f}},    // 6: upper left, magenta
}};
// Six triangles, each the centre and two neighbouring rim corners. Every rim
// vertex is used twice and the centre six times, but stored once.
constexpr std::array<uint16_t, 18> indices{
    0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 1,
};
// [/hexagon]

// [memory-types]
// Every memory type the device offers, with the heap it comes from. Printed
// once at start, so you can see what your driver offers.
void print_memory_types(VkPhysicalDevice physical) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        const VkMemoryType& type = memory.memoryTypes[i];
        const VkMemoryHeap& heap = memory.memoryHeaps[type.heapIndex];
        std::string flags;
        if (type.propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) flags += " DEVICE_LOCAL";
        if (type.propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) flags += " HOST_VISIBLE";
        if (type.propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) flags += " HOST_COHERENT";
        if (type.propertyFlags & VK_MEMORY_PROPERTY_HOST_CACHED_BIT) flags += " HOST_CACHED";
        if (flags.empty()) flags = " (none)";
        std::fprintf(stderr, "05_vertex_buffers: memory type %u: heap %u (%llu MiB%s):%s\n", i,
                     type.heapIndex, (unsigned long long)(heap.size >> 20),
                     heap.flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT ? ", device-local" : "",
                     flags.c_str());
    }
}

// The first memory type that the resource allows (bit i of `allowed` set) and
// that has every property we want. Vulkan lists types with fewer properties
// before types with more, and faster before slower, so the first match is the
// one to take.
uint32_t choose_memory_type(VkPhysicalDevice physical, uint32_t allowed,
                            VkMemoryPropertyFlags wanted) {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((allowed & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    throw vkt::Error("no memory type has the properties this buffer needs");
}
// [/memory-types]

// [create-buffer]
// A buffer is only a name and a size; memory is allocated separately and
// bound to it. (vkt::create_buffer is this function, plus a vkMapMemory for
// host-visible memory.)
vkt::Buffer create_buffer(VkPhysicalDevice physical, VkDevice device, VkDeviceSize size,
                          VkBufferUsageFlags usage, VkMemoryPropertyFlags wanted) {
    vkt::Buffer out;
    out.size = size;
    VkBufferCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = size,
        .usage = usage,                            // what it may be used for
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,  // one queue family uses it
    };
    VkBuffer buffer;
    VKT_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
    out.buffer = vkt::BufferHandle(device, buffer);

    // The driver says how much memory the buffer needs (at least `size`), its
    // alignment, and which memory types it may live in.
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, buffer, &requirements);
    VkMemoryAllocateInfo allocate{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = requirements.size,
        .memoryTypeIndex = choose_memory_type(physical, requirements.memoryTypeBits, wanted),
    };
    VkDeviceMemory memory;
    VKT_CHECK(vkAllocateMemory(device, &allocate, nullptr, &memory));
    out.memory = vkt::DeviceMemory(device, memory);
    VKT_CHECK(vkBindBufferMemory(device, buffer, memory, 0));  // at offset 0
    return out;
}
// [/create-buffer]

// [upload]
// A device-local buffer holding a copy of data[0..size): written by the CPU
// into a host-visible staging buffer, then copied by the GPU. (This is
// vkt::create_device_buffer.)
vkt::Buffer upload(const vkt::Context& context, const void* data, VkDeviceSize size,
                   VkBufferUsageFlags usage) {
    VkDevice device = context.device;
    // 1. The staging buffer: memory the CPU can map, and coherent, so what we
    //    write needs no vkFlushMappedMemoryRanges to reach the GPU.
    vkt::Buffer staging =
        create_buffer(context.physical, device, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    void* mapped;
    VKT_CHECK(vkMapMemory(device, staging.memory, 0, size, 0, &mapped));
    std::memcpy(mapped, data, size);
    vkUnmapMemory(device, staging.memory);

    // 2. The real buffer, in device-local memory, which the CPU may not see.
    vkt::Buffer buffer =
        create_buffer(context.physical, device, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);

    // 3. A command buffer recorded once, for this copy only.
    vkt::CommandPool pool = vkt::create_command_pool(device, context.queue_family,
                                                     VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
    VkCommandBufferAllocateInfo allocate{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
        .commandPool = pool,
        .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
        .commandBufferCount = 1,
    };
    VkCommandBuffer cmd;  // freed with the pool
    VKT_CHECK(vkAllocateCommandBuffers(device, &allocate, &cmd));
    VkCommandBufferBeginInfo begin{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
        .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT,
    };
    VKT_CHECK(vkBeginCommandBuffer(cmd, &begin));
    VkBufferCopy region{.srcOffset = 0, .dstOffset = 0, .size = size};
    vkCmdCopyBuffer(cmd, staging.buffer, buffer.buffer, 1, &region);

    // 4. The copy's writes must be visible to the vertex input stage that
    //    reads vertices and indices in later frames. The fence below only
    //    tells the CPU that the copy is done; it makes nothing visible to
    //    the GPU's own later reads. This barrier does.
    VkMemoryBarrier2 barrier{
        .sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
        .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
        .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
        .dstStageMask = VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT,
        .dstAccessMask = VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT,
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .memoryBarrierCount = 1,
        .pMemoryBarriers = &barrier,
    };
    vkCmdPipelineBarrier2(cmd, &dependency);
    VKT_CHECK(vkEndCommandBuffer(cmd));

    // 5. Submit and wait: the staging buffer may only be destroyed (when this
    //    function returns) after the GPU has read it.
    vkt::Fence done = vkt::create_fence(device, false);
    VkCommandBufferSubmitInfo command{
        .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO,
        .commandBuffer = cmd,
    };
    VkSubmitInfo2 submit{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO_2,
        .commandBufferInfoCount = 1,
        .pCommandBufferInfos = &command,
    };
    VKT_CHECK(vkQueueSubmit2(context.queue, 1, &submit, done));
    VkFence fence = done;
    VKT_CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
    return buffer;
}
// [/upload]

class Hexagon : public vkt::Renderer {
public:
    explicit Hexagon(const vkt::Context& context) {
        VkDevice device = context.device;
        print_memory_types(context.physical);

        // [buffers]
        vertex_buffer_ =
            upload(context, vertices.data(), sizeof(vertices), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        index_buffer_ =
            upload(context, indices.data(), sizeof(indices), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
        // [/buffers]

        // [vertex-input]
        // One binding: buffer slot 0 holds whole Vertex structs back to back,
        // and the next one is read for every vertex (not every instance).
        VkVertexInputBindingDescription binding{
            .binding = 0,
            .stride = sizeof(Vertex),
            .inputRate = VK_VERTEX_INPUT_RATE_VERTEX,
        };
        // Two attributes in that binding: where each shader input comes from
        // in a Vertex, and in what format.
        VkVertexInputAttributeDescription attributes[] = {
            {
                .location = 0,  // layout(location = 0) in vec2 position
                .binding = 0,
                .format = VK_FORMAT_R32G32_SFLOAT,
                .offset = offsetof(Vertex, position),
            },
            {
                .location = 1,  // layout(location = 1) in vec3 colour_in
                .binding = 0,
                .format = VK_FORMAT_R32G32B32_SFLOAT,
                .offset = offsetof(Vertex, colour),
            },
        };
        // [/vertex-input]

        // [pipeline]
        // Chapter 04's pipeline in one call; only the vertex input is new.
        vkt::ShaderModule vertex = vkt::load_shader(device, context.chapter, "hexagon.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device, context.chapter, "hexagon.frag");
        layout_ = vkt::create_pipeline_layout(device);
        pipeline_ =
            vkt::create_graphics_pipeline(device, {
                                                      .vertex = vertex,
                                                      .fragment = fragment,
                                                      .layout = layout_,
                                                      .bindings = {&binding, 1},
                                                      .attributes = attributes,
                                                      .color_formats = {context.color_format},
                                                  });
        // [/pipeline]
    }

    void record(const vkt::Frame& frame) override {
        // Clear to chapter 04's dark blue-grey, keep what we draw: chapter 04's
        // vkCmdBeginRendering and its two structs, now one call (vkt/resources/rendering.hpp).
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.02f, 0.02f, 0.04f, 1.0f}});
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);

        // [draw]
        // Binding 0 reads from the vertex buffer, from its start; indices are
        // 16-bit. Then 18 indices make 6 triangles: one instance, from index
        // 0, adding 0 to every index, first instance 0.
        VkBuffer vertex_buffers[] = {vertex_buffer_.buffer};
        VkDeviceSize offsets[] = {0};
        vkCmdBindVertexBuffers(frame.cmd, 0, 1, vertex_buffers, offsets);
        vkCmdBindIndexBuffer(frame.cmd, index_buffer_.buffer, 0, VK_INDEX_TYPE_UINT16);
        vkCmdDrawIndexed(frame.cmd, uint32_t(indices.size()), 1, 0, 0, 0);
        // [/draw]
        vkCmdEndRendering(frame.cmd);
    }

private:
    vkt::Buffer vertex_buffer_;
    vkt::Buffer index_buffer_;
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    return vkt::run_chapter(
        argc, argv, {.name = "05_vertex_buffers", .title = "05 - vertex buffers"},
        [](const vkt::Context& context) { return std::make_unique<Hexagon>(context); });
}
