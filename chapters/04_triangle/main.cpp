// Chapter 04: the first triangle.
//
// Three new things: shader modules (SPIR-V compiled from GLSL at build time),
// the graphics pipeline (every fixed-function setting spelled out), and
// dynamic rendering (vkCmdBeginRendering names the image we draw into, no
// render pass or framebuffer objects). The runner from chapter 03 does the
// rest.

#include "vkt/core/files.hpp"
#include "vkt/core/owned.hpp"
#include "vkt/frame/runner.hpp"

#include <cstring>

namespace {

// [shader-module]
// A shader module wraps SPIR-V words. The file is read whole; SPIR-V is a
// stream of 32-bit words that starts with the magic number 0x07230203. We
// check both: a driver handed anything else may crash rather than fail.
vkt::ShaderModule load_shader(VkDevice device, const std::string& chapter, const char* name) {
    const auto path = vkt::shader_path(chapter, name);
    std::vector<char> code = vkt::read_file(path);
    uint32_t magic = 0;
    if (code.size() >= 4) std::memcpy(&magic, code.data(), 4);
    if (code.size() % 4 != 0 || magic != 0x07230203)
        throw vkt::Error(path.string() + " is not SPIR-V (rebuild the chapter's shaders)");
    VkShaderModuleCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
        .codeSize = code.size(),
        .pCode = reinterpret_cast<const uint32_t*>(code.data()),
    };
    VkShaderModule module;
    VKT_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
    return vkt::ShaderModule(device, module);
}
// [/shader-module]

class Triangle : public vkt::Renderer {
public:
    explicit Triangle(const vkt::Context& context) {
        VkDevice device = context.device;
        // The modules are only needed while the pipeline is created.
        vkt::ShaderModule vertex = load_shader(device, context.chapter, "triangle.vert");
        vkt::ShaderModule fragment = load_shader(device, context.chapter, "triangle.frag");

        // [layout]
        // What the shaders read besides vertices: nothing yet (descriptors
        // come in chapter 07, push constants in chapter 06).
        VkPipelineLayoutCreateInfo layout_info{.sType =
                                                   VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        VkPipelineLayout layout;
        VKT_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout));
        layout_ = vkt::PipelineLayout(device, layout);
        // [/layout]

        // [stages]
        VkPipelineShaderStageCreateInfo stages[] = {
            {
                .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                .stage = VK_SHADER_STAGE_VERTEX_BIT,
                .module = vertex,
                .pName = "main",
            },
            {
                .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
                .module = fragment,
                .pName = "main",
            },
        };
        // [/stages]

        // [fixed-function]
        // No vertex attributes: the vertex shader makes its own positions.
        VkPipelineVertexInputStateCreateInfo vertex_input{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        };
        VkPipelineInputAssemblyStateCreateInfo input_assembly{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
            .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST,
        };
        // Viewport and scissor are set per frame (dynamic state), so a resized
        // window needs no new pipeline; here we only say there is one of each.
        VkPipelineViewportStateCreateInfo viewport{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
            .viewportCount = 1,
            .scissorCount = 1,
        };
        VkPipelineRasterizationStateCreateInfo rasterization{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
            .polygonMode = VK_POLYGON_MODE_FILL,
            .cullMode = VK_CULL_MODE_NONE,  // one triangle: nothing to hide
            .frontFace = VK_FRONT_FACE_CLOCKWISE,
            .lineWidth = 1.0f,
        };
        VkPipelineMultisampleStateCreateInfo multisample{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
            .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT,
        };
        // Write all four channels, no blending: the fragment replaces the pixel.
        VkPipelineColorBlendAttachmentState blend_attachment{
            .blendEnable = VK_FALSE,
            .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                              VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT,
        };
        VkPipelineColorBlendStateCreateInfo blend{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
            .attachmentCount = 1,
            .pAttachments = &blend_attachment,
        };
        VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
        VkPipelineDynamicStateCreateInfo dynamic{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
            .dynamicStateCount = 2,
            .pDynamicStates = dynamic_states,
        };
        // [/fixed-function]

        // [pipeline]
        // With dynamic rendering the pipeline names the formats it draws into
        // instead of a render pass: here, the runner's _SRGB colour target.
        VkPipelineRenderingCreateInfo rendering{
            .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
            .colorAttachmentCount = 1,
            .pColorAttachmentFormats = &context.color_format,
        };
        VkGraphicsPipelineCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
            .pNext = &rendering,
            .stageCount = 2,
            .pStages = stages,
            .pVertexInputState = &vertex_input,
            .pInputAssemblyState = &input_assembly,
            .pViewportState = &viewport,
            .pRasterizationState = &rasterization,
            .pMultisampleState = &multisample,
            .pColorBlendState = &blend,
            .pDynamicState = &dynamic,
            .layout = layout_,
        };
        VkPipeline pipeline;
        VKT_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
        pipeline_ = vkt::Pipeline(device, pipeline);
        // [/pipeline]
    }

    void record(const vkt::Frame& frame) override {
        // [begin-rendering]
        // Clear to a dark blue-grey when rendering begins, keep the result.
        VkRenderingAttachmentInfo colour{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = frame.target_view,
            .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.color = {{0.02f, 0.02f, 0.04f, 1.0f}}},
        };
        VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .renderArea = {{0, 0}, frame.extent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &colour,
        };
        vkCmdBeginRendering(frame.cmd, &rendering);
        // [/begin-rendering]

        // [draw]
        VkViewport viewport{0.0f, 0.0f, float(frame.extent.width), float(frame.extent.height),
                            0.0f, 1.0f};
        VkRect2D scissor{{0, 0}, frame.extent};
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        vkCmdSetViewport(frame.cmd, 0, 1, &viewport);
        vkCmdSetScissor(frame.cmd, 0, 1, &scissor);
        vkCmdDraw(frame.cmd, 3, 1, 0, 0);  // three vertices, one instance
        vkCmdEndRendering(frame.cmd);
        // [/draw]
    }

private:
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    return vkt::run_chapter(
        argc, argv, {.name = "04_triangle", .title = "04 - triangle"},
        [](const vkt::Context& context) { return std::make_unique<Triangle>(context); });
}
