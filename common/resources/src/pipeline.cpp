#include "vkt/resources/pipeline.hpp"

#include "vkt/core/check.hpp"

namespace vkt {

PipelineLayout create_pipeline_layout(VkDevice device,
                                      std::span<const VkDescriptorSetLayout> set_layouts,
                                      std::span<const VkPushConstantRange> push_constants) {
    VkPipelineLayoutCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
        .setLayoutCount = uint32_t(set_layouts.size()),
        .pSetLayouts = set_layouts.data(),
        .pushConstantRangeCount = uint32_t(push_constants.size()),
        .pPushConstantRanges = push_constants.data(),
    };
    VkPipelineLayout layout;
    VKT_CHECK(vkCreatePipelineLayout(device, &info, nullptr, &layout));
    return PipelineLayout(device, layout);
}

Pipeline create_graphics_pipeline(VkDevice device, const GraphicsPipelineDesc& desc) {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    stages.push_back({
        .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
        .stage = VK_SHADER_STAGE_VERTEX_BIT,
        .module = desc.vertex,
        .pName = "main",
        .pSpecializationInfo = desc.vertex_specialization,
    });
    if (desc.fragment)
        stages.push_back({
            .sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
            .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
            .module = desc.fragment,
            .pName = "main",
            .pSpecializationInfo = desc.fragment_specialization,
        });
    VkPipelineVertexInputStateCreateInfo vertex_input{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = uint32_t(desc.bindings.size()),
        .pVertexBindingDescriptions = desc.bindings.data(),
        .vertexAttributeDescriptionCount = uint32_t(desc.attributes.size()),
        .pVertexAttributeDescriptions = desc.attributes.data(),
    };
    VkPipelineInputAssemblyStateCreateInfo input_assembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
        .topology = desc.topology,
    };
    VkPipelineViewportStateCreateInfo viewport{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
        .viewportCount = 1,
        .scissorCount = 1,
    };
    VkPipelineRasterizationStateCreateInfo rasterization{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .polygonMode = desc.polygon_mode,
        .cullMode = desc.cull_mode,
        .frontFace = desc.front_face,
        .depthBiasEnable =
            desc.depth_bias_constant != 0.0f || desc.depth_bias_slope != 0.0f ? VK_TRUE : VK_FALSE,
        .depthBiasConstantFactor = desc.depth_bias_constant,
        .depthBiasSlopeFactor = desc.depth_bias_slope,
        .lineWidth = 1.0f,
    };
    // [multisample]
    // Chapter 21: how many samples the rasteriser covers per pixel, and
    // whether the fragment shader runs once per pixel (its colour written to
    // every covered sample) or for a fraction of the samples on their own.
    VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = desc.samples,
        .sampleShadingEnable = desc.min_sample_shading > 0.0f ? VK_TRUE : VK_FALSE,
        .minSampleShading = desc.min_sample_shading,
        .pSampleMask = nullptr,  // every sample may be written
        .alphaToCoverageEnable = VK_FALSE,
        .alphaToOneEnable = VK_FALSE,
    };
    // [/multisample]
    const bool depth = desc.depth_format != VK_FORMAT_UNDEFINED;
    VkPipelineDepthStencilStateCreateInfo depth_stencil{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = depth ? VK_TRUE : VK_FALSE,
        .depthWriteEnable = depth && desc.depth_write ? VK_TRUE : VK_FALSE,
        .depthCompareOp = desc.depth_compare,
    };
    VkPipelineColorBlendAttachmentState blend_attachment{
        .blendEnable = desc.alpha_blend ? VK_TRUE : VK_FALSE,
        .srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA,
        .dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
        .colorBlendOp = VK_BLEND_OP_ADD,
        .srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE,
        .dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
        .alphaBlendOp = VK_BLEND_OP_ADD,
        .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                          VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT,
    };
    std::vector<VkPipelineColorBlendAttachmentState> blend_attachments(desc.color_formats.size(),
                                                                       blend_attachment);
    VkPipelineColorBlendStateCreateInfo blend{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
        .attachmentCount = uint32_t(blend_attachments.size()),
        .pAttachments = blend_attachments.data(),
    };
    VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
        .dynamicStateCount = 2,
        .pDynamicStates = dynamic_states,
    };
    VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = uint32_t(desc.color_formats.size()),
        .pColorAttachmentFormats = desc.color_formats.data(),
        .depthAttachmentFormat = desc.depth_format,
    };
    VkGraphicsPipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
        .pNext = &rendering,
        .stageCount = uint32_t(stages.size()),
        .pStages = stages.data(),
        .pVertexInputState = &vertex_input,
        .pInputAssemblyState = &input_assembly,
        .pViewportState = &viewport,
        .pRasterizationState = &rasterization,
        .pMultisampleState = &multisample,
        .pDepthStencilState = &depth_stencil,
        .pColorBlendState = &blend,
        .pDynamicState = &dynamic,
        .layout = desc.layout,
    };
    VkPipeline pipeline;
    VKT_CHECK(vkCreateGraphicsPipelines(device, desc.cache, 1, &info, nullptr, &pipeline));
    return Pipeline(device, pipeline);
}

void set_viewport_and_scissor(VkCommandBuffer cmd, VkExtent2D extent) {
    VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

}  // namespace vkt
