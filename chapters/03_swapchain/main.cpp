// Chapter 03: the swapchain and the frame loop.
//
// Everything that turns commands into pictures on a screen lives in the
// runner (common/frame/src/runner.cpp and common/core/src/swapchain.cpp), which this
// chapter's page walks through: the surface, the swapchain, acquiring and
// presenting images, semaphores and fences, two frames in flight, and
// recreating the swapchain when the window changes size. Every later chapter
// uses that runner and only says what to record into each frame.
//
// What this chapter records is the simplest visible thing: it clears the
// frame's image to a colour that changes with time. Clearing is a transfer
// command, so it needs the image in a transfer layout, and getting it there
// (and back) is our first pipeline barrier.

#include "vkt/frame/runner.hpp"

#include <cmath>

namespace {

class ClearScreen : public vkt::Renderer {
public:
    void record(const vkt::Frame& frame) override {
        // [clear-colour]
        // A slow walk around the colour wheel, in linear RGB (the _SRGB target
        // encodes it for the display). Headless, time is frame index / 60 s.
        const float t = float(frame.time);
        VkClearColorValue colour{{0.5f + 0.5f * std::sin(t), 0.5f + 0.5f * std::sin(t + 2.094f),
                                  0.5f + 0.5f * std::sin(t + 4.189f), 1.0f}};
        // [/clear-colour]

        // [to-transfer]
        // The runner hands us the image in COLOR_ATTACHMENT_OPTIMAL, ready for
        // drawing (chapter 04). vkCmdClearColorImage is a transfer command and
        // wants TRANSFER_DST_OPTIMAL. The barrier says: after the runner's own
        // transition (at the colour-output stage), change the layout, and make
        // the image ready for the clear's transfer write.
        VkImageSubresourceRange whole{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageMemoryBarrier2 to_transfer{
            .sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
            .srcStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            .srcAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            .dstStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT,
            .dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
            .oldLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            .newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
            .image = frame.target,
            .subresourceRange = whole,
        };
        VkDependencyInfo dependency{
            .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
            .imageMemoryBarrierCount = 1,
            .pImageMemoryBarriers = &to_transfer,
        };
        vkCmdPipelineBarrier2(frame.cmd, &dependency);
        // [/to-transfer]

        // [clear]
        vkCmdClearColorImage(frame.cmd, frame.target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour,
                             1, &whole);
        // [/clear]

        // [to-attachment]
        // And back, as the runner's contract asks: the clear's write must be
        // done before anything at the colour-output stage touches the image.
        VkImageMemoryBarrier2 to_attachment = to_transfer;
        to_attachment.srcStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
        to_attachment.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        to_attachment.dstStageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        to_attachment.dstAccessMask = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        to_attachment.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        to_attachment.newLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        dependency.pImageMemoryBarriers = &to_attachment;
        vkCmdPipelineBarrier2(frame.cmd, &dependency);
        // [/to-attachment]
    }
};

}  // namespace

// [main]
int main(int argc, char** argv) {
    // The clear is a transfer command, into whichever image the frame is.
    return vkt::run_chapter(
        argc, argv,
        {.name = "03_swapchain", .title = "03 - swapchain", .transfers_into_target = true},
        [](const vkt::Context&) { return std::make_unique<ClearScreen>(); });
}
// [/main]
