#pragma once
// The mesh shader pipeline, taught in chapter 26: a graphics pipeline whose
// geometry stages are a task and a mesh shader, every struct written out
// (vkt::create_graphics_pipeline, chapters 04-08, knows only vertex
// shaders). Chapter 28's task path makes one too, with reversed depth.

#include "vkt/core/check.hpp"
#include "vkt/core/owned.hpp"

namespace vkt {

// [mesh-pipeline]
// A graphics pipeline whose geometry stages are a task and a mesh shader:
// no vertex input state and no input assembly state (the mesh shader
// makes the primitives); the rest is as for any pipeline. The mesh shader's
// workgroup size is its specialization constant 0; the depth test passes
// what `depth_compare` says (LESS, or GREATER with reversed depth).
inline Pipeline create_mesh_pipeline(VkDevice device, VkPipelineLayout layout, VkShaderModule task,
                                     VkShaderModule mesh, uint32_t mesh_workgroup,
                                     VkShaderModule fragment, VkFormat colour_format,
                                     VkFormat depth_format,
                                     VkCompareOp depth_compare = VK_COMPARE_OP_LESS) {
    const VkSpecializationMapEntry workgroup_entry{
        .constantID = 0, .offset = 0, .size = sizeof(uint32_t)};
    const VkSpecializationInfo workgroup{.mapEntryCount = 1,
                                         .pMapEntries = &workgroup_entry,
                                         .dataSize = sizeof(uint32_t),
                                         .pData = &mesh_workgroup};
    const VkPipelineShaderStageCreateInfo stages[] = {
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_TASK_BIT_EXT,
         .module = task,
         .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_MESH_BIT_EXT,
         .module = mesh,
         .pName = "main",
         .pSpecializationInfo = &workgroup},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
         .module = fragment,
         .pName = "main"},
    };
    const VkPipelineViewportStateCreateInfo viewport{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
        .viewportCount = 1,
        .scissorCount = 1,
    };
    // Back faces still culled per triangle, after the task shader's
    // per-meshlet cull (which catches only meshlets wholly facing away).
    const VkPipelineRasterizationStateCreateInfo raster{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .polygonMode = VK_POLYGON_MODE_FILL,
        .cullMode = VK_CULL_MODE_BACK_BIT,
        .frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE,
        .lineWidth = 1.0f,
    };
    const VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT,
    };
    const VkPipelineDepthStencilStateCreateInfo depth{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = VK_TRUE,
        .depthWriteEnable = VK_TRUE,
        .depthCompareOp = depth_compare,
    };
    const VkPipelineColorBlendAttachmentState blend_attachment{
        .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                          VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT,
    };
    const VkPipelineColorBlendStateCreateInfo blend{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
        .attachmentCount = 1,
        .pAttachments = &blend_attachment,
    };
    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    const VkPipelineDynamicStateCreateInfo dynamic{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
        .dynamicStateCount = 2,
        .pDynamicStates = dynamic_states,
    };
    const VkPipelineRenderingCreateInfo rendering{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
        .colorAttachmentCount = 1,
        .pColorAttachmentFormats = &colour_format,
        .depthAttachmentFormat = depth_format,
    };
    const VkGraphicsPipelineCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
        .pNext = &rendering,
        .stageCount = 3,
        .pStages = stages,
        .pVertexInputState = nullptr,    // ignored with a mesh shader
        .pInputAssemblyState = nullptr,  // likewise
        .pViewportState = &viewport,
        .pRasterizationState = &raster,
        .pMultisampleState = &multisample,
        .pDepthStencilState = &depth,
        .pColorBlendState = &blend,
        .pDynamicState = &dynamic,
        .layout = layout,
    };
    VkPipeline pipeline;
    VKT_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return Pipeline(device, pipeline);
}
// [/mesh-pipeline]

}  // namespace vkt
