#pragma once
// Chapter 20's compute passes share one pipeline layout of three sets, each
// set owned by the pass that makes its buffers, its bindings named there:
//
//   set 0  TransformPass (transform_pass.hpp), one per frame in flight: the
//          scene's coordinates and objects, the poses, the projected vertices
//   set 1  ComputeRaster (compute_raster.hpp): the line ends, the pixels, the palette
//   set 2  BinnedRaster (binned_raster.hpp): the objects' lines and boxes, the work list
//
// and one block of push constants for every stage (Push, ndim.glsl). A pass
// reads what an earlier pass wrote through that pass's set: the rasterisers
// read the projected vertices through set 0. The pose pass (pose_pass.hpp)
// and the resolve pass (resolve_pass.hpp) have layouts of their own.

#include "scene_state.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"

#include <vector>

namespace ch20 {

constexpr VkShaderStageFlags push_stages =
    VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// A set layout of `count` storage buffers, bindings 0 .. count - 1, for compute.
inline vkt::DescriptorSetLayout storage_set_layout(VkDevice device, uint32_t count) {
    std::vector<VkDescriptorSetLayoutBinding> bindings(count);
    for (uint32_t b = 0; b < count; ++b)
        bindings[b] = {.binding = b,
                       .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                       .descriptorCount = 1,
                       .stageFlags = VK_SHADER_STAGE_COMPUTE_BIT};
    return vkt::create_descriptor_set_layout(device, bindings);
}

// A pool for `sets` sets of `count` storage buffers each.
inline vkt::DescriptorPool storage_pool(VkDevice device, uint32_t sets, uint32_t count) {
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, sets * count};
    return vkt::create_descriptor_pool(device, sets, {&size, 1});
}

struct Layouts {
    vkt::DescriptorSetLayout transform, raster, bins;  // sets 0, 1, 2
    vkt::PipelineLayout pipeline;
};

}  // namespace ch20
