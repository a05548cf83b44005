// Chapter 21's multisampling: the sample counts a device offers and the
// --samples check (chapters/21_multisampling/sample_counts.hpp); and, on
// whatever device the loader offers, the helpers that chapter made ready
// for later ones: vkt::create_attachment_image and vkt::create_depth_image
// with samples and transient memory, GraphicsPipelineDesc::samples, and
// vkt::begin_rendering's resolve, drawing one edge at 1x and at 4x.
#include "../../chapters/21_multisampling/sample_counts.hpp"
#include "vkt/core/barrier.hpp"
#include "vkt/core/device.hpp"
#include "vkt/core/instance.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/resources/depth.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/readback.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/upload.hpp"

#include <catch2/catch_test_macros.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>

#include <glm/glm.hpp>

#include <cstdlib>
#include <optional>
#include <set>
#include <vector>

using Catch::Matchers::ContainsSubstring;

namespace {

VkPhysicalDeviceLimits sample_limits(VkSampleCountFlags colour, VkSampleCountFlags depth) {
    VkPhysicalDeviceLimits limits{};
    limits.framebufferColorSampleCounts = colour;
    limits.framebufferDepthSampleCounts = depth;
    return limits;
}

}  // namespace

TEST_CASE("offered_sample_counts: what colour and depth both allow", "[multisample]") {
    // Lavapipe: 1 and 4 for both.
    CHECK(offered_sample_counts(sample_limits(0x5, 0x5)) == 0x5);
    // More samples for colour than for depth: only the common ones count.
    CHECK(offered_sample_counts(sample_limits(0x1f, 0x0f)) == 0x0f);
    CHECK(offered_sample_counts(sample_limits(0x0b, 0x0d)) == 0x09);  // 1 and 8
}

TEST_CASE("sample_count_list names the counts in a mask", "[multisample]") {
    CHECK(sample_count_list(VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT) == "1, 4");
    CHECK(sample_count_list(0x7f) == "1, 2, 4, 8, 16, 32, 64");
    CHECK(sample_count_list(VK_SAMPLE_COUNT_8_BIT) == "8");
    CHECK(sample_count_list(0) == "none");
}

TEST_CASE("checked_sample_count accepts what is offered and names the rest", "[multisample]") {
    const VkSampleCountFlags lavapipe = VK_SAMPLE_COUNT_1_BIT | VK_SAMPLE_COUNT_4_BIT;
    CHECK(checked_sample_count(1, lavapipe, "llvmpipe") == VK_SAMPLE_COUNT_1_BIT);
    CHECK(checked_sample_count(4, lavapipe, "llvmpipe") == VK_SAMPLE_COUNT_4_BIT);
    CHECK(checked_sample_count(8, 0x0f, "a GPU") == VK_SAMPLE_COUNT_8_BIT);
    CHECK_THROWS_AS(checked_sample_count(8, lavapipe, "llvmpipe"), vkt::Error);
    CHECK_THROWS_WITH(checked_sample_count(2, lavapipe, "llvmpipe"),
                      "--samples 2: llvmpipe cannot render a colour and depth target with 2 "
                      "samples per pixel (it offers 1, 4)");
    // Not a power of two, or past the largest Vulkan count: never offered,
    // whatever bits the mask has.
    CHECK_THROWS_WITH(checked_sample_count(3, 0x7f, "x"), ContainsSubstring("it offers 1, 2, 4"));
    CHECK_THROWS_AS(checked_sample_count(0, 0x7f, "x"), vkt::Error);
    CHECK_THROWS_AS(checked_sample_count(128, 0xff, "x"), vkt::Error);
}

namespace {

// Chapter 21's vertex (scene.vert): position, colour, striped.
struct Vertex {
    glm::vec3 position;
    glm::vec3 colour;
    float striped;
};

// Draws one white triangle on black into a 16x16 RGBA8 UNORM target with
// `samples` per pixel (resolved by begin_rendering where more than one) and
// multisampled depth, and returns the distinct red values of the picture.
std::set<int> draw_edge(const vkt::Device& device, VkSampleCountFlagBits samples) {
    const vkt::Gpu gpu{device.physical(), device, device.queue(), device.queue_family()};
    constexpr VkExtent2D extent{16, 16};
    constexpr VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
    vkt::Image target =
        vkt::create_image_2d(device.physical(), device, format, extent,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT);
    vkt::Image samples_image;
    if (msaa)
        samples_image = vkt::create_attachment_image(device.physical(), device, format, extent,
                                                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                                     VK_IMAGE_ASPECT_COLOR_BIT, samples, true);
    const VkFormat depth_format = vkt::choose_depth_format(device.physical());
    vkt::Image depth =
        vkt::create_depth_image(device.physical(), device, depth_format, extent, samples, msaa);
    REQUIRE(depth.samples == samples);

    // An edge from the bottom-left corner to the right side, 0.8 of the way
    // up: no pixel centre on it, every slope of coverage along it.
    const Vertex vertices[] = {{{-1.0f, 1.0f, 0.5f}, glm::vec3(1.0f), 0.0f},
                               {{1.0f, -0.6f, 0.5f}, glm::vec3(1.0f), 0.0f},
                               {{1.0f, 1.0f, 0.5f}, glm::vec3(1.0f), 0.0f}};
    vkt::Buffer vertex_buffer = vkt::create_device_buffer(gpu, vertices, sizeof vertices,
                                                          VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    const VkVertexInputBindingDescription binding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, position)},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(Vertex, colour)},
        {2, 0, VK_FORMAT_R32_SFLOAT, offsetof(Vertex, striped)},
    };
    const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
    vkt::PipelineLayout layout = vkt::create_pipeline_layout(device, {}, {&push, 1});
    vkt::ShaderModule vertex = vkt::load_shader(device, "21_multisampling", "scene.vert");
    vkt::ShaderModule fragment = vkt::load_shader(device, "21_multisampling", "scene.frag");
    vkt::Pipeline pipeline = vkt::create_graphics_pipeline(device, {
                                                                       .vertex = vertex,
                                                                       .fragment = fragment,
                                                                       .layout = layout,
                                                                       .bindings = {&binding, 1},
                                                                       .attributes = attributes,
                                                                       .color_formats = {format},
                                                                       .depth_format = depth_format,
                                                                       .samples = samples,
                                                                   });
    vkt::Readback readback;
    vkt::one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        constexpr VkPipelineStageFlags2 output = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        constexpr VkAccessFlags2 read_write =
            VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_UNDEFINED,
                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, output, 0, output, read_write);
        if (msaa)
            vkt::image_barrier(cmd, samples_image.image, VK_IMAGE_LAYOUT_UNDEFINED,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, output, 0, output,
                               read_write);
        vkt::begin_depth_frame(cmd, depth.image);
        vkt::begin_rendering(cmd, msaa ? VkImageView(samples_image.view) : VkImageView(target.view),
                             extent, {{0.0f, 0.0f, 0.0f, 1.0f}}, depth.view,
                             msaa ? VkImageView(target.view) : VK_NULL_HANDLE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
        vkt::set_viewport_and_scissor(cmd, extent);
        const VkBuffer buffer = vertex_buffer.buffer;
        const VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
        const glm::mat4 identity(1.0f);
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof identity, &identity);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
        // The resolve wrote the target in COLOR_ATTACHMENT_OUTPUT.
        vkt::image_barrier(cmd, target.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, output,
                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_TRANSFER_READ_BIT);
        vkt::record_readback(device.physical(), device, cmd, target.image, format, extent,
                             readback);
    });
    const vkt::RgbaImage picture = vkt::to_rgba(readback.buffer.mapped, extent, format);
    std::set<int> reds;
    for (size_t i = 0; i < picture.pixels.size(); i += 4) reds.insert(picture.pixels[i]);
    return reds;
}

}  // namespace

TEST_CASE("multisampled images, pipelines and the resolve of begin_rendering on a device",
          "[multisample][gpu]") {
    std::optional<vkt::Instance> instance;
    try {
        instance.emplace(vkt::InstanceConfig{
            .application_name = "test_multisample",
            .validation = vkt::instance_layer_available(vkt::validation_layer_name)});
    } catch (const std::exception& e) {
        SKIP("no Vulkan instance: " << e.what());
    }
    vkt::DeviceRequirements requirements{.features = {VKT_FEATURE_12(separateDepthStencilLayouts)}};
    const auto candidates = vkt::survey_devices(*instance, VK_NULL_HANDLE, requirements);
    bool any = false;
    for (const auto& candidate : candidates) any = any || candidate.unsuitable.empty();
    if (!any) SKIP("no Vulkan device can run chapter 21");
    {
        vkt::Device device(vkt::choose_device(candidates, ""), requirements);
        VkPhysicalDeviceProperties properties;
        vkGetPhysicalDeviceProperties(device.physical(), &properties);
        if (!(offered_sample_counts(properties.limits) & VK_SAMPLE_COUNT_4_BIT))
            SKIP("the device cannot render with 4 samples");

        // The defaults are the single-sample images every chapter had.
        constexpr VkExtent2D extent{64, 32};
        const VkFormat depth_format = vkt::choose_depth_format(device.physical());
        vkt::Image one = vkt::create_depth_image(device.physical(), device, depth_format, extent);
        CHECK(one.samples == VK_SAMPLE_COUNT_1_BIT);
        CHECK_FALSE(one.lazily_allocated);
        CHECK(one.bytes >= VkDeviceSize{64} * 32 * 2);
        vkt::Image four = vkt::create_depth_image(device.physical(), device, depth_format, extent,
                                                  VK_SAMPLE_COUNT_4_BIT, true);
        CHECK(four.samples == VK_SAMPLE_COUNT_4_BIT);
        CHECK(four.bytes >= 4 * VkDeviceSize{64} * 32 * 2);  // every sample has its depth
        // Transient memory is lazily allocated exactly where the device has
        // a memory type for it (lavapipe has none).
        VkPhysicalDeviceMemoryProperties memory;
        vkGetPhysicalDeviceMemoryProperties(device.physical(), &memory);
        bool lazy_type = false;
        for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
            lazy_type = lazy_type || (memory.memoryTypes[i].propertyFlags &
                                      VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT);
        CHECK(four.lazily_allocated == lazy_type);
        vkt::Image colour = vkt::create_attachment_image(
            device.physical(), device, VK_FORMAT_R8G8B8A8_UNORM, extent,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
        CHECK(colour.samples == VK_SAMPLE_COUNT_1_BIT);
        CHECK(colour.bytes >= VkDeviceSize{64} * 32 * 4);

        // One sample per pixel: every pixel is black or white. Four,
        // resolved: the pixels the edge crosses are grey.
        const std::set<int> aliased = draw_edge(device, VK_SAMPLE_COUNT_1_BIT);
        CHECK(aliased == std::set<int>{0, 255});
        const std::set<int> resolved = draw_edge(device, VK_SAMPLE_COUNT_4_BIT);
        CHECK(resolved.contains(0));
        CHECK(resolved.contains(255));
        INFO("distinct red values at 4x: " << resolved.size());
        CHECK(resolved.size() >= 3);
        // A pixel with k of its 4 samples covered averages to k/4 of white:
        // 63.75, 127.5 or 191.25 of 255, give or take the rounding.
        for (int red : resolved) {
            INFO("red " << red);
            const bool quarter = red == 0 || red == 255 || std::abs(red - 64) <= 1 ||
                                 std::abs(red - 128) <= 1 || std::abs(red - 191) <= 1;
            CHECK(quarter);
        }
    }
    // Everything is destroyed: the layer saw no misuse and no hazard.
    CHECK(instance->counts()->warnings == 0);
    CHECK(instance->counts()->errors == 0);
}
