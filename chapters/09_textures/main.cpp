// Chapter 09: textures.
//
// A picture on the floor. Four new things: images (a VkImage, its memory and
// a view), layouts and the barriers that change them, a full mip chain made
// with blits (or on the CPU where the format cannot be blit-filtered), and
// samplers. The floor recedes to the horizon under a perspective camera, so
// every mip level is in use at once: `--mips none` shows what goes wrong
// without them.

#include "vkt/core/files.hpp"
#include "vkt/frame/runner.hpp"
#include "vkt/resources/descriptors.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/rendering.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/resources/texture.hpp"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <span>
#include <vector>

namespace {

// [load]
// Decoding is not Vulkan's business: vkt::decode_image hands PNG to libpng
// and JPEG to libjpeg-turbo, and asks both for 8-bit RGBA whatever the file
// holds (alpha 255 where it has none). vkt::load_image_file reads the file's
// first bytes (a PNG's or a JPEG's signature, or a refusal) before the whole
// of it, and names it when it is missing, a directory or past 1 GiB. The
// budget (--max-memory) is judged from the file's size and the image's
// header, before a pixel is decoded: what the pixels will cost decoded,
// staged and on the GPU with their mips.
vkt::RgbaImage load_texture(const std::filesystem::path& path, vkt::MemoryBudget& budget) {
    return vkt::load_image_file(path, budget);
}
// [/load]

// [barrier]
// One layout transition of mip levels [first, first + count), with the
// synchronisation around it: the work in src_stage that did src_access must
// finish (and its writes be made available) before the layout changes, and
// the work in dst_stage that does dst_access waits for the change.
void transition(VkCommandBuffer cmd, VkImage image, uint32_t first, uint32_t count,
                VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src_stage,
                VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stage,
                VkAccessFlags2 dst_access) {
    VkImageMemoryBarrier2 barrier{
        .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
        .srcStageMask = src_stage,
        .srcAccessMask = src_access,
        .dstStageMask = dst_stage,
        .dstAccessMask = dst_access,
        .oldLayout = from,
        .newLayout = to,
        .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,  // no change of owner
        .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
        .image = image,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, first, count, 0, 1},
    };
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
        .imageMemoryBarrierCount = 1,
        .pImageMemoryBarriers = &barrier,
    };
    vkCmdPipelineBarrier2(cmd, &dependency);
}
// [/barrier]

// Where the texture is read: by the fragment shader, through a sampler.
constexpr VkPipelineStageFlags2 kSampling = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkAccessFlags2 kSampledRead = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;

// An image of `levels` mip levels holding `pixels` in level 0; with mips
// "blit" the other levels are made on the GPU, with "cpu" they are made here
// and uploaded, with "none" there are none. Left in SHADER_READ_ONLY_OPTIMAL.
vkt::Image upload_texture(const vkt::Context& context, const vkt::RgbaImage& pixels,
                          const std::string& mips) {
    VkDevice device = context.device;
    vkt::Image out;
    out.format = VK_FORMAT_R8G8B8A8_SRGB;  // the file holds sRGB-encoded colours
    out.extent = {pixels.width, pixels.height};
    out.mip_levels = mips == "none" ? 1 : vkt::mip_level_count(pixels.width, pixels.height);

    // [create-image]
    VkImageCreateInfo image_info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
        .imageType = VK_IMAGE_TYPE_2D,
        .format = out.format,
        .extent = {pixels.width, pixels.height, 1},
        .mipLevels = out.mip_levels,
        .arrayLayers = 1,
        .samples = VK_SAMPLE_COUNT_1_BIT,
        // OPTIMAL: texels arranged however the GPU samples fastest (not rows).
        .tiling = VK_IMAGE_TILING_OPTIMAL,
        // Copied into, blitted from and to (the mips), and sampled.
        .usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                 VK_IMAGE_USAGE_SAMPLED_BIT,
        .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED,
    };
    VkImage image;
    VKT_CHECK(vkCreateImage(device, &image_info, nullptr, &image));
    out.image = vkt::ImageHandle(device, image);

    // Like a buffer, an image gets its memory separately; the driver says how
    // much (more than width * height * 4: the mips, and its own layout).
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, image, &requirements);
    VkMemoryAllocateInfo allocate{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
        .allocationSize = requirements.size,
        .memoryTypeIndex = vkt::find_memory_type(context.physical, requirements.memoryTypeBits,
                                                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT),
    };
    VkDeviceMemory memory;
    VKT_CHECK(vkAllocateMemory(device, &allocate, nullptr, &memory));
    out.memory = vkt::DeviceMemory(device, memory);
    VKT_CHECK(vkBindImageMemory(device, image, memory, 0));
    // [/create-image]

    // [create-view]
    // Shaders see an image through a view: which aspect, which mip levels and
    // layers, and how to read its format. Ours sees all of it.
    VkImageViewCreateInfo view_info{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image,
        .viewType = VK_IMAGE_VIEW_TYPE_2D,
        .format = out.format,
        .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, out.mip_levels, 0, 1},
    };
    VkImageView view;
    VKT_CHECK(vkCreateImageView(device, &view_info, nullptr, &view));
    out.view = vkt::ImageView(device, view);
    // [/create-view]

    // [staging]
    // The levels to upload: level 0, or every level when the CPU makes them.
    // Level 0 is the decoded picture itself, not a copy (at 8192 x 8192 a
    // copy would be 256 MiB that --max-memory does not count).
    std::vector<vkt::RgbaImage> cpu_levels;
    if (mips == "cpu") cpu_levels = vkt::generate_mips_cpu(pixels, /*srgb=*/true);
    const std::span<const vkt::RgbaImage> levels =
        mips == "cpu" ? std::span<const vkt::RgbaImage>(cpu_levels) : std::span(&pixels, 1);
    VkDeviceSize total = 0;
    for (const auto& level : levels) total += level.pixels.size();
    vkt::Buffer staging =
        vkt::create_host_buffer(context.gpu(), total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t i = 0; i < levels.size(); ++i) {
        std::memcpy(static_cast<char*>(staging.mapped) + offset, levels[i].pixels.data(),
                    levels[i].pixels.size());
        regions.push_back({
            .bufferOffset = offset,
            .bufferRowLength = 0,  // 0: rows follow each other tightly
            .bufferImageHeight = 0,
            .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1},  // mip level i
            .imageOffset = {0, 0, 0},
            .imageExtent = {levels[i].width, levels[i].height, 1},
        });
        offset += levels[i].pixels.size();
    }
    // [/staging]

    vkt::one_time_submit(context.gpu(), [&](VkCommandBuffer cmd) {
        // [copy]
        // UNDEFINED -> TRANSFER_DST_OPTIMAL for every level: the old contents
        // (there are none) may be dropped. Both writers of the image, the
        // copy and the blits, wait for the change.
        transition(cmd, image, 0, out.mip_levels, VK_IMAGE_LAYOUT_UNDEFINED,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                   VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
                   VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(cmd, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               uint32_t(regions.size()), regions.data());
        if (mips != "blit") {  // every level is written: all of them to sampling
            transition(cmd, image, 0, out.mip_levels, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT, kSampling, kSampledRead);
            return;
        }
        // [/copy]

        // [blit-mips]
        // Level i is level i - 1 scaled to half size with linear filtering.
        // Each level is written (by the copy or a blit), then read by the next
        // blit, then sampled: three layouts, one after the other.
        for (uint32_t i = 1; i < out.mip_levels; ++i) {
            transition(cmd, image, i - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       i == 1 ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_BLIT_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                       VK_ACCESS_2_TRANSFER_READ_BIT);
            VkExtent2D src = vkt::mip_extent(pixels.width, pixels.height, i - 1);
            VkExtent2D dst = vkt::mip_extent(pixels.width, pixels.height, i);
            VkImageBlit blit{
                .srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i - 1, 0, 1},
                .srcOffsets = {{0, 0, 0}, {int32_t(src.width), int32_t(src.height), 1}},
                .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1},
                .dstOffsets = {{0, 0, 0}, {int32_t(dst.width), int32_t(dst.height), 1}},
            };
            vkCmdBlitImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
            // Level i - 1 is finished once the blit has read it.
            transition(cmd, image, i - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_BLIT_BIT,
                       VK_ACCESS_2_NONE, kSampling, kSampledRead);
        }
        // The smallest level was only written, never read.
        transition(
            cmd, image, out.mip_levels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            out.mip_levels == 1 ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_BLIT_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT, kSampling, kSampledRead);
        // [/blit-mips]
    });  // waits: the staging buffer may go now
    return out;
}

struct Push {
    glm::mat4 view_projection;
    float scroll;
};

class Textures : public vkt::Renderer {
public:
    explicit Textures(const vkt::Context& context) {
        VkDevice device = context.device;
        const auto& options = context.options;
        std::filesystem::path file = options.has("--texture")
                                         ? std::filesystem::path(options.text("--texture"))
                                         : vkt::asset_path("textures/checker.png");
        vkt::MemoryBudget budget(uint64_t(options.integer("--max-memory")));
        vkt::RgbaImage pixels = load_texture(file, budget);
        const uint32_t max_size = context.properties.limits.maxImageDimension2D;
        if (pixels.width > max_size || pixels.height > max_size)
            throw vkt::Error(vkt::shown_path(file) + ": larger than this device's " +
                             std::to_string(max_size) + " texel limit");

        // [format-check]
        // A linear blit of R8G8B8A8_SRGB is not guaranteed: ask the device.
        std::string mips = options.text("--mips");
        VkFormatProperties format_properties;
        vkGetPhysicalDeviceFormatProperties(context.physical, VK_FORMAT_R8G8B8A8_SRGB,
                                            &format_properties);
        const VkFormatFeatureFlags blit_features =
            VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT |
            VK_FORMAT_FEATURE_BLIT_DST_BIT;
        if (mips == "blit" &&
            (format_properties.optimalTilingFeatures & blit_features) != blit_features) {
            std::fprintf(stderr,
                         "09_textures: this device cannot blit-filter R8G8B8A8_SRGB: "
                         "making the mips on the CPU\n");
            mips = "cpu";
        }
        // [/format-check]
        // Mips made on the CPU are a chain in memory of its own before the
        // staging copy, level 0 included: 4/3 of the pixels again.
        if (mips == "cpu")
            budget.charge(uint64_t(pixels.pixels.size()) * 4 / 3,
                          vkt::shown_path(file) + ": its mip chain, made on the CPU");
        texture_ = upload_texture(context, pixels, mips);

        // [sampler]
        // Anisotropic filtering is an optional feature (ChapterSpec below asks
        // for it); its strength is capped by the device and by --anisotropy.
        float anisotropy = std::min(float(options.number("--anisotropy")),
                                    context.properties.limits.maxSamplerAnisotropy);
        if (!context.features.has(VKT_FEATURE_10(samplerAnisotropy))) anisotropy = 0.0f;
        VkSamplerCreateInfo sampler_info{
            .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
            .magFilter = VK_FILTER_LINEAR,                // magnified: blend the 4 nearest texels
            .minFilter = VK_FILTER_LINEAR,                // minified: the same, within a mip level
            .mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR,  // and blend the 2 nearest levels
            .addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT,  // uv 1.25 reads 0.25
            .addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT,
            .addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT,
            .mipLodBias = 0.0f,
            .anisotropyEnable = anisotropy > 1.0f ? VK_TRUE : VK_FALSE,
            .maxAnisotropy = std::max(anisotropy, 1.0f),
            .compareEnable = VK_FALSE,  // comparison is for shadow maps
            .compareOp = VK_COMPARE_OP_ALWAYS,
            .minLod = 0.0f,
            .maxLod = VK_LOD_CLAMP_NONE,                      // every level the image has
            .borderColor = VK_BORDER_COLOR_INT_OPAQUE_BLACK,  // unused with REPEAT
            .unnormalizedCoordinates = VK_FALSE,              // uv in 0..1, not texels
        };
        VkSampler sampler;
        VKT_CHECK(vkCreateSampler(device, &sampler_info, nullptr, &sampler));
        sampler_ = vkt::Sampler(device, sampler);
        // [/sampler]

        const std::string filtering =
            anisotropy > 1.0f ? std::to_string(int(anisotropy)) + "x anisotropic filtering"
            : context.features.has(VKT_FEATURE_10(samplerAnisotropy))
                ? "anisotropic filtering off"
                : "anisotropic filtering off (the device has no samplerAnisotropy)";
        std::fprintf(stderr, "09_textures: %s, %ux%u, %u mip level%s (%s), %s\n",
                     vkt::shown_path(file.filename()).c_str(), pixels.width, pixels.height,
                     texture_.mip_levels, texture_.mip_levels == 1 ? "" : "s", mips.c_str(),
                     filtering.c_str());

        // [descriptors]
        // One binding, a COMBINED_IMAGE_SAMPLER: image view and sampler
        // together, read by the fragment shader (chapter 07 built the helpers).
        VkDescriptorSetLayoutBinding binding{
            .binding = 0,
            .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
            .descriptorCount = 1,
            .stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT,
        };
        set_layout_ = vkt::create_descriptor_set_layout(device, {&binding, 1});
        VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
        pool_ = vkt::create_descriptor_pool(device, 1, {&size, 1});
        set_ = vkt::allocate_descriptor_set(device, pool_, set_layout_);
        // The layout the image will be in whenever a shader reads it.
        vkt::write_image_descriptor(device, set_, 0, texture_.view, sampler_,
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        // [/descriptors]

        vkt::ShaderModule vertex = vkt::load_shader(device, context.chapter, "floor.vert");
        vkt::ShaderModule fragment = vkt::load_shader(device, context.chapter, "floor.frag");
        VkDescriptorSetLayout set_layouts[] = {set_layout_};
        VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push)};
        layout_ = vkt::create_pipeline_layout(device, set_layouts, {&push, 1});
        pipeline_ =
            vkt::create_graphics_pipeline(device, {
                                                      .vertex = vertex,
                                                      .fragment = fragment,
                                                      .layout = layout_,
                                                      .color_formats = {context.color_format},
                                                  });
    }

    void record(const vkt::Frame& frame) override {
        // A camera 1 m above the floor, looking slightly down along -z; the
        // texture slides towards it at 0.5 m/s (headless: frame index / 60).
        const float aspect = float(frame.extent.width) / float(frame.extent.height);
        glm::mat4 projection = glm::perspective(glm::radians(60.0f), aspect, 0.1f, 300.0f);
        projection[1][1] *= -1.0f;  // Vulkan's clip space has y down
        glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -6.0f),
                                     glm::vec3(0.0f, 1.0f, 0.0f));
        Push push{projection * view, float(frame.time) * 0.5f};

        // A sky-blue clear: linear (0.25, 0.45, 0.80).
        vkt::begin_rendering(frame.cmd, frame.target_view, frame.extent,
                             {{0.25f, 0.45f, 0.80f, 1.0f}});
        // [draw]
        vkCmdBindPipeline(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
        VkDescriptorSet set = set_;
        vkCmdBindDescriptorSets(frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set, 0,
                                nullptr);
        vkCmdPushConstants(frame.cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(Push), &push);
        vkt::set_viewport_and_scissor(frame.cmd, frame.extent);
        vkCmdDraw(frame.cmd, 6, 1, 0, 0);  // the floor: two triangles
        // [/draw]
        vkCmdEndRendering(frame.cmd);
    }

private:
    vkt::Image texture_;
    vkt::Sampler sampler_;
    vkt::DescriptorSetLayout set_layout_;
    vkt::DescriptorPool pool_;
    VkDescriptorSet set_ = VK_NULL_HANDLE;  // freed with its pool
    vkt::PipelineLayout layout_;
    vkt::Pipeline pipeline_;
};

}  // namespace

int main(int argc, char** argv) {
    // [spec]
    vkt::ChapterSpec spec{.name = "09_textures", .title = "09 - textures"};
    // Used when the device has it; the chapter asks Context::features.
    spec.requirements.optional_features = {VKT_FEATURE_10(samplerAnisotropy)};
    spec.options = {
        {.name = "--texture",
         .type = vkt::OptionType::text,
         .value_name = "FILE",
         .help = "the image on the floor, PNG or JPEG (default: assets/textures/checker.png)"},
        {.name = "--mips",
         .type = vkt::OptionType::choice,
         .help = "make the mip levels with GPU blits, on the CPU, or not at all",
         .default_value = "blit",
         .choices = {"blit", "cpu", "none"}},
        {.name = "--anisotropy",
         .type = vkt::OptionType::number,
         .value_name = "N",
         .help = "the most anisotropic filtering to use (1: off)",
         .default_value = "16",
         .min = 1,
         .max = 16},
        vkt::max_memory_option(),
    };
    // [/spec]
    return vkt::run_chapter(argc, argv, spec, [](const vkt::Context& context) {
        return std::make_unique<Textures>(context);
    });
}
