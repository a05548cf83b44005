#pragma once
// Chapter 23's cube maps (environment.hpp): an image of six square layers
// that the scene samples by direction and compute shaders write texel by
// texel, with a view of every mip level and one of each level alone; and
// the sampler that reads them.

#include "vkt/core/check.hpp"
#include "vkt/core/memory.hpp"
#include "vkt/resources/upload.hpp"

#include <vector>

struct CubeMap {
    vkt::Image image;                   // its view: a CUBE view of every level
    std::vector<vkt::ImageView> level;  // a CUBE view of each level alone
};

inline vkt::ImageView cube_view(VkDevice device, VkImage image, VkFormat format, uint32_t level,
                                uint32_t levels) {
    const VkImageViewCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image,
        .viewType = VK_IMAGE_VIEW_TYPE_CUBE,
        .format = format,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, levels, 0, 6},
    };
    VkImageView view;
    VKT_CHECK(vkCreateImageView(device, &info, nullptr, &view));
    return {device, view};
}

// [cube-image]
// A cube map is a 2D image of six layers, one per face (+X, -X, +Y, -Y, +Z,
// -Z), made CUBE_COMPATIBLE so that a CUBE view may see them as one. Compute
// shaders write it as a storage image (an imageCube: x, y and the face); the
// scene samples it by direction.
inline CubeMap make_cube(const vkt::Gpu& gpu, uint32_t size, uint32_t levels, VkFormat format) {
    const VkImageCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = format,
        .extent = {size, size, 1},
        .mipLevels = levels,
        .arrayLayers = 6,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        .tiling = VK_IMAGE_TILING_OPTIMAL,
        .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
    };
    VkImage image;
    VKT_CHECK(vkCreateImage(gpu.device, &info, nullptr, &image));
    CubeMap cube;
    cube.image.image = vkt::ImageHandle(gpu.device, image);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(gpu.device, image, &requirements);
    cube.image.memory = vkt::allocate_memory(gpu.physical, gpu.device, requirements,
                                             VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VKT_CHECK(vkBindImageMemory(gpu.device, image, cube.image.memory, 0));
    cube.image.view = cube_view(gpu.device, image, format, 0, levels);
    for (uint32_t level = 0; level < levels; ++level)
        cube.level.push_back(cube_view(gpu.device, image, format, level, 1));
    return cube;
}
// [/cube-image]

// [ibl-sampler]
inline vkt::Sampler clamped_sampler(VkDevice device) {
    // Linear within and between levels (the specular cube's roughness
    // steps), and clamped: the table's n.v of 1 must not wrap round to 0.
    // A cube ignores the address modes: it filters into the next face.
    const VkSamplerCreateInfo sampler_info{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = VK_FILTER_LINEAR,
        .minFilter = VK_FILTER_LINEAR,
        .mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR,
        .addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
        .maxLod = VK_LOD_CLAMP_NONE,
    };
    VkSampler sampler;
    VKT_CHECK(vkCreateSampler(device, &sampler_info, nullptr, &sampler));
    return {device, sampler};
}
// [/ibl-sampler]
