#pragma once
// Chapter 17's lighting pass for --shade fragment: chapter 16's full-screen
// triangle, with a fragment shader that loops over its tile's list alone
// (tiled_lighting.frag). With --verify, the same pass into float targets, and
// chapter 16's own brute-force lighting.frag as the reference. And for
// --shade lists, the same lighting as a compute pass (tiled_lighting.comp):
// one invocation per pixel, its tile's list read from memory as the fragment
// shader reads it, so that the two differ only in how the pixels are launched.

#include "tile_pass.hpp"
#include "vkt/resources/compute.hpp"
#include "vkt/resources/pipeline.hpp"
#include "vkt/resources/shader.hpp"
#include "vkt/scene/gbuffer_pass.hpp"

namespace ch17 {

class LightingPass {
public:
    enum Which { tiled, tiled_float, brute_float };  // the float ones only with --verify

    LightingPass(const vkt::Context& context, VkPipelineLayout layout, VkFormat verify_format) {
        const VkDevice device = context.device;
        vkt::ShaderModule fullscreen = vkt::load_shader(device, context.chapter, "fullscreen.vert");
        vkt::ShaderModule tiled_frag =
            vkt::load_shader(device, context.chapter, "tiled_lighting.frag");
        vkt::ShaderModule brute_frag = vkt::load_shader(device, context.chapter, "lighting.frag");
        auto lighting = [&](VkShaderModule fragment, VkFormat target) {
            return vkt::create_graphics_pipeline(device, {.vertex = fullscreen,
                                                          .fragment = fragment,
                                                          .layout = layout,
                                                          .color_formats = {target}});
        };
        pipelines_[Which::tiled] = lighting(tiled_frag, context.color_format);
        lists_ = vkt::create_compute_pipeline(
            device, vkt::load_shader(device, context.chapter, "tiled_lighting.comp"), layout);
        if (verify_format != VK_FORMAT_UNDEFINED) {  // float targets: nothing rounded or clamped
            pipelines_[Which::tiled_float] = lighting(tiled_frag, verify_format);
            pipelines_[Which::brute_float] = lighting(brute_frag, verify_format);
        }
    }

    // [lighting]
    // --shade fragment: one full-screen triangle, lit from the tiles' lists.
    void draw(VkCommandBuffer cmd, const PassSets& sets, VkExtent2D extent, VkImageView target,
              Which which, const void* push, uint32_t push_size) const {
        vkt::deferred::begin_full_screen(cmd, target, extent);  // as chapter 16's
        sets.bind(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_[which], push, push_size);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    // [/lighting]

    // [lighting-lists]
    // --shade lists: one workgroup per tile, one invocation per pixel, into
    // the tile pass's float image (which is then copied to the target).
    void dispatch(VkCommandBuffer cmd, const PassSets& sets, VkExtent2D extent,
                  const TilePass& tiles, int32_t view) const {
        tiles.image_to_write(cmd);
        sets.bind(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, lists_, &view, sizeof view);
        const vkt::TileGrid grid = vkt::tile_grid(extent.width, extent.height, tile_size);
        vkCmdDispatch(cmd, grid.x, grid.y, 1);
        tiles.image_to_copy(cmd);
    }
    // [/lighting-lists]

private:
    vkt::Pipeline pipelines_[3];
    vkt::Pipeline lists_;
};

}  // namespace ch17
