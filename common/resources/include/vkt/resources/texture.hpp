#pragma once
// Textures: the tidy form of chapter 09. Decode a PNG or JPEG into RGBA bytes
// (decode_image, in image_io.hpp), upload it into a sampled image with a full
// mip chain (generated on the GPU with vkCmdBlitImage where the format allows
// linear blits, else on the CPU with a box filter), and make a sampler for it.

#include "vkt/core/memory.hpp"
#include "vkt/resources/image_io.hpp"
#include "vkt/resources/upload.hpp"

#include <cstdint>
#include <vector>

namespace vkt {

// The number of levels in a full mip chain: floor(log2(max(w, h))) + 1,
// down to 1x1 (1024x1024: 11, 640x480: 10, 1x1: 1). 0 for an empty image.
uint32_t mip_level_count(uint32_t width, uint32_t height);

// The size of mip level `level` of a width x height image: halved per level,
// rounded down, never below 1.
VkExtent2D mip_extent(uint32_t width, uint32_t height, uint32_t level);

// The CPU fallback for mip generation: the next level down, each texel the
// average of the 2x2 texels above it (an odd last row or column is left
// out; a side one texel wide is averaged with itself). With srgb, R, G and B are averaged in linear
// light (decoded from sRGB, averaged, encoded again), as a blit of an _SRGB image does; alpha, and
// everything when !srgb, is averaged as stored. Rounds to nearest.
RgbaImage downsample_box(const RgbaImage& level, bool srgb);

// Every level of the chain, level 0 (a copy of base) first.
std::vector<RgbaImage> generate_mips_cpu(const RgbaImage& base, bool srgb);

// Whether vkCmdBlitImage with VK_FILTER_LINEAR can make the mips of an
// optimally tiled image of this format: SAMPLED_IMAGE_FILTER_LINEAR, BLIT_SRC
// and BLIT_DST in its optimalTilingFeatures.
bool can_blit_mips(VkPhysicalDevice physical, VkFormat format);

enum class MipGeneration {
    automatic,  // blit where can_blit_mips says so, else cpu
    blit,       // vkCmdBlitImage level by level (throws Error where unsupported)
    cpu,        // downsample_box on the CPU, every level uploaded
    none,       // one level only: what minification looks like without mips
};

struct Texture {
    Image image;  // R8G8B8A8_SRGB or _UNORM, image.mip_levels levels, SHADER_READ_ONLY_OPTIMAL
    Sampler sampler;
};

// A linear, repeating sampler over every mip level (maxLod VK_LOD_CLAMP_NONE)
// with linear blending between levels. max_anisotropy 0 turns anisotropic
// filtering off; above 0 the device must have been created with the
// samplerAnisotropy feature, and the value must be at most
// limits.maxSamplerAnisotropy.
Sampler create_sampler(VkDevice device, float max_anisotropy);

// Uploads `pixels` into a new image (R8G8B8A8_SRGB for colour, _UNORM with
// !srgb: normal maps, roughness...), generates its mips, and leaves it in
// SHADER_READ_ONLY_OPTIMAL, visible to every later command on the queue; the
// sampler is create_sampler(gpu.device, max_anisotropy). Waits for the GPU.
Texture create_texture(const Gpu& gpu, const RgbaImage& pixels, bool srgb, float max_anisotropy,
                       MipGeneration mips = MipGeneration::automatic);

}  // namespace vkt
