#pragma once
// A graphics pipeline in one call: the tidy form of chapter 04's pipeline,
// with chapter 05's vertex input, chapter 06's push constants, chapter 08's
// depth test, chapter 21's multisampling, chapter 22's depth bias and
// chapter 27's pipeline cache as options. Later chapters name only what
// differs from the defaults; a chapter that teaches a pipeline setting writes
// it out itself.

#include "vkt/core/owned.hpp"

#include <span>
#include <vector>

namespace vkt {

PipelineLayout create_pipeline_layout(VkDevice device,
                                      std::span<const VkDescriptorSetLayout> set_layouts = {},
                                      std::span<const VkPushConstantRange> push_constants = {});

struct GraphicsPipelineDesc {
    VkShaderModule vertex = VK_NULL_HANDLE;
    VkShaderModule fragment = VK_NULL_HANDLE;  // may be null (a depth-only pass)
    VkPipelineLayout layout = VK_NULL_HANDLE;
    std::span<const VkVertexInputBindingDescription> bindings;      // chapter 05
    std::span<const VkVertexInputAttributeDescription> attributes;  // chapter 05
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPolygonMode polygon_mode = VK_POLYGON_MODE_FILL;
    VkCullModeFlags cull_mode = VK_CULL_MODE_NONE;
    // Counter-clockwise in framebuffer coordinates (y down): see the
    // conventions appendix for why a y-flipped projection keeps glTF's CCW.
    VkFrontFace front_face = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    std::vector<VkFormat> color_formats;
    // Chapter 08: set to test and write depth (compare LESS by default).
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    bool depth_write = true;
    VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
    // Chapter 22: where either is not 0, the depth written is pushed back by
    // constant * the format's smallest step + slope * the triangle's depth
    // slope (a shadow map's bias against acne).
    float depth_bias_constant = 0.0f;
    float depth_bias_slope = 0.0f;
    bool alpha_blend = false;  // source-over blending on every colour attachment
    // Chapter 21: samples per pixel of every attachment the pipeline draws
    // into; and, where above 0, sample shading: the fragment shader runs for
    // at least this fraction of the samples separately (needs the device
    // feature sampleRateShading).
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    float min_sample_shading = 0.0f;
    const VkSpecializationInfo* vertex_specialization = nullptr;
    const VkSpecializationInfo* fragment_specialization = nullptr;
    // Chapter 27: a pipeline cache to look the compiled shaders up in and add
    // them to (none: every pipeline is compiled from scratch).
    VkPipelineCache cache = VK_NULL_HANDLE;
};

// Viewport and scissor are dynamic state (set them each frame).
Pipeline create_graphics_pipeline(VkDevice device, const GraphicsPipelineDesc& desc);

// vkCmdSetViewport and vkCmdSetScissor for the whole of `extent`.
void set_viewport_and_scissor(VkCommandBuffer cmd, VkExtent2D extent);

}  // namespace vkt
