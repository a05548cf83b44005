#include "vkt/resources/texture.hpp"

#include "vkt/core/barrier.hpp"

#include "vkt/core/check.hpp"
#include "vkt/resources/srgb.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

namespace vkt {

uint32_t mip_level_count(uint32_t width, uint32_t height) {
    // floor(log2(n)) + 1 is the number of bits n needs.
    return uint32_t(std::bit_width(std::max(width, height)));
}

VkExtent2D mip_extent(uint32_t width, uint32_t height, uint32_t level) {
    return {std::max(1u, width >> level), std::max(1u, height >> level)};
}

namespace {

const std::array<float, 256>& srgb_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[size_t(i)] = srgb_to_linear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

uint8_t to_byte(float value01) {
    return uint8_t(std::lround(std::clamp(value01, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

RgbaImage downsample_box(const RgbaImage& level, bool srgb) {
    if (level.width == 0 || level.height == 0 ||
        level.pixels.size() != size_t(level.width) * level.height * 4)
        throw Error("downsample_box: the image is empty or its pixels do not match its size");
    const auto& linear = srgb_table();
    RgbaImage out;
    out.width = std::max(1u, level.width / 2);
    out.height = std::max(1u, level.height / 2);
    out.pixels.resize(size_t(out.width) * out.height * 4);
    for (uint32_t y = 0; y < out.height; ++y) {
        for (uint32_t x = 0; x < out.width; ++x) {
            const uint32_t xs[2] = {std::min(2 * x, level.width - 1),
                                    std::min(2 * x + 1, level.width - 1)};
            const uint32_t ys[2] = {std::min(2 * y, level.height - 1),
                                    std::min(2 * y + 1, level.height - 1)};
            for (uint32_t c = 0; c < 4; ++c) {
                const bool decode = srgb && c < 3;
                float sum = 0;
                for (uint32_t sy : ys)
                    for (uint32_t sx : xs) {
                        uint8_t v = level.pixels[(size_t(sy) * level.width + sx) * 4 + c];
                        sum += decode ? linear[v] : float(v) / 255.0f;
                    }
                const float mean = sum / 4.0f;
                out.pixels[(size_t(y) * out.width + x) * 4 + c] =
                    to_byte(decode ? linear_to_srgb(mean) : mean);
            }
        }
    }
    return out;
}

std::vector<RgbaImage> generate_mips_cpu(const RgbaImage& base, bool srgb) {
    std::vector<RgbaImage> levels{base};
    const uint32_t count = mip_level_count(base.width, base.height);
    for (uint32_t i = 1; i < count; ++i) levels.push_back(downsample_box(levels.back(), srgb));
    return levels;
}

bool can_blit_mips(VkPhysicalDevice physical, VkFormat format) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(physical, format, &properties);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                        VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                                        VK_FORMAT_FEATURE_BLIT_DST_BIT;
    return (properties.optimalTilingFeatures & needed) == needed;
}

Sampler create_sampler(VkDevice device, float max_anisotropy) {
    VkSamplerCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = VK_FILTER_LINEAR,
        .minFilter = VK_FILTER_LINEAR,
        .mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR,
        .addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT,
        .addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT,
        .addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT,
        .mipLodBias = 0.0f,
        .anisotropyEnable = max_anisotropy > 0.0f ? VK_TRUE : VK_FALSE,
        .maxAnisotropy = max_anisotropy > 0.0f ? max_anisotropy : 1.0f,
        .compareEnable = VK_FALSE,
        .compareOp = VK_COMPARE_OP_ALWAYS,
        .minLod = 0.0f,
        .maxLod = VK_LOD_CLAMP_NONE,
        .borderColor = VK_BORDER_COLOR_INT_OPAQUE_BLACK,
        .unnormalizedCoordinates = VK_FALSE,
    };
    VkSampler sampler;
    VKT_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
    return Sampler(device, sampler);
}

namespace {

// One image barrier over mip levels [base, base + count).
void mip_barrier(VkCommandBuffer cmd, VkImage image, uint32_t base, uint32_t count,
                 VkImageLayout old_layout, VkImageLayout new_layout,
                 VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                 VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    image_barrier(cmd, image, {VK_IMAGE_ASPECT_COLOR_BIT, base, count, 0, 1}, old_layout,
                  new_layout, src_stage, src_access, dst_stage, dst_access);
}

// Where a sampled texture is read from: any shader stage of any later command.
constexpr VkPipelineStageFlags2 kReaders = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
constexpr VkAccessFlags2 kRead = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;

}  // namespace

Texture create_texture(const Gpu& gpu, const RgbaImage& pixels, bool srgb, float max_anisotropy,
                       MipGeneration mips) {
    if (pixels.width == 0 || pixels.height == 0 ||
        pixels.pixels.size() != size_t(pixels.width) * pixels.height * 4)
        throw Error("create_texture: the image is empty or its pixels do not match its size");
    // [texture-format]
    const VkFormat format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    // [/texture-format]
    if (mips == MipGeneration::automatic)
        mips = can_blit_mips(gpu.physical, format) ? MipGeneration::blit : MipGeneration::cpu;
    if (mips == MipGeneration::blit && !can_blit_mips(gpu.physical, format))
        throw Error("create_texture: this device cannot blit-filter its texture format");

    // What goes into the staging buffer: level 0, or (cpu) every level.
    std::vector<RgbaImage> cpu_levels;
    if (mips == MipGeneration::cpu) cpu_levels = generate_mips_cpu(pixels, srgb);
    std::span<const RgbaImage> uploads = mips == MipGeneration::cpu
                                             ? std::span<const RgbaImage>(cpu_levels)
                                             : std::span<const RgbaImage>(&pixels, 1);
    const uint32_t levels =
        mips == MipGeneration::none ? 1 : mip_level_count(pixels.width, pixels.height);

    VkDeviceSize total = 0;
    for (const RgbaImage& level : uploads) total += level.pixels.size();
    Buffer staging = create_host_buffer(gpu, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t i = 0; i < uploads.size(); ++i) {
        std::memcpy(static_cast<char*>(staging.mapped) + offset, uploads[i].pixels.data(),
                    uploads[i].pixels.size());
        regions.push_back({
            .bufferOffset = offset,
            .bufferRowLength = 0,  // rows tightly packed
            .bufferImageHeight = 0,
            .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1},
            .imageOffset = {0, 0, 0},
            .imageExtent = {uploads[i].width, uploads[i].height, 1},
        });
        offset += uploads[i].pixels.size();
    }

    Texture texture;
    texture.image = create_image_2d_mips(
        gpu.physical, gpu.device, format, {pixels.width, pixels.height}, levels,
        VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
            VK_IMAGE_USAGE_SAMPLED_BIT,
        VK_IMAGE_ASPECT_COLOR_BIT);
    VkImage image = texture.image.image;

    one_time_submit(gpu, [&](VkCommandBuffer cmd) {
        mip_barrier(cmd, image, 0, levels, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                    VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT);  // the copy and the blits write after it
        vkCmdCopyBufferToImage(cmd, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(regions.size()), regions.data());
        if (mips != MipGeneration::blit) {
            mip_barrier(cmd, image, 0, levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, kReaders, kRead);
            return;
        }
        // Level i is made from level i - 1: that one becomes a blit source
        // (after its copy or blit has written it), then, once read, final.
        for (uint32_t i = 1; i < levels; ++i) {
            const VkPipelineStageFlags2 writer =
                i == 1 ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_BLIT_BIT;
            mip_barrier(cmd, image, i - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, writer,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT);
            const VkExtent2D src = mip_extent(pixels.width, pixels.height, i - 1);
            const VkExtent2D dst = mip_extent(pixels.width, pixels.height, i);
            VkImageBlit blit{
                .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i - 1, 0, 1},
                .srcOffsets = {{0, 0, 0}, {int32_t(src.width), int32_t(src.height), 1}},
                .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1},
                .dstOffsets = {{0, 0, 0}, {int32_t(dst.width), int32_t(dst.height), 1}},
            };
            vkCmdBlitImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            mip_barrier(cmd, image, i - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                        VK_ACCESS_2_NONE, kReaders, kRead);
        }
        // The last level was only written (by the copy, if it is level 0).
        mip_barrier(cmd, image, levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    levels == 1 ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_BLIT_BIT,
                    VK_ACCESS_2_TRANSFER_WRITE_BIT, kReaders, kRead);
    });

    texture.sampler = create_sampler(gpu.device, max_anisotropy);
    return texture;
}

}  // namespace vkt
