// The runner's contract for how a chapter leaves its target
// (vkt/frame/runner.hpp): the chapter names the layout and the stage and
// access of its last write, and the runner's next barrier waits for exactly
// those; the layout alone is not taken to say which stage wrote.
#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"

#include <catch2/catch_test_macros.hpp>

namespace {

const VkImage target = reinterpret_cast<VkImage>(uintptr_t{0x1234});

VkImageMemoryBarrier2 to_copy(const vkt::TargetWrite& written) {
    return vkt::barrier_after(written, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
}

}  // namespace

TEST_CASE("the barrier after record() waits for the write the chapter names", "[runner]") {
    // A fragment shader's storage write left in GENERAL: the barrier starts
    // at the fragment stage, not at the compute stage GENERAL is also used by.
    const vkt::TargetWrite fragment{VK_IMAGE_LAYOUT_GENERAL,
                                    VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    const VkImageMemoryBarrier2 after_fragment = to_copy(fragment);
    CHECK(after_fragment.srcStageMask == VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    CHECK(after_fragment.srcAccessMask == VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    CHECK(after_fragment.oldLayout == VK_IMAGE_LAYOUT_GENERAL);
    CHECK(after_fragment.newLayout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    CHECK(after_fragment.dstStageMask == VK_PIPELINE_STAGE_2_COPY_BIT);
    CHECK(after_fragment.dstAccessMask == VK_ACCESS_2_TRANSFER_READ_BIT);
    CHECK(after_fragment.image == target);

    // A ray-tracing shader's store (chapter 25 could write its target so).
    const vkt::TargetWrite traced{VK_IMAGE_LAYOUT_GENERAL,
                                  VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR,
                                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    CHECK(to_copy(traced).srcStageMask == VK_PIPELINE_STAGE_2_RAY_TRACING_SHADER_BIT_KHR);

    // The three the chapters use.
    CHECK(to_copy(vkt::stored_by_compute).srcStageMask == VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    CHECK(to_copy(vkt::drawn_by_colour_output).srcAccessMask ==
          VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    CHECK(to_copy(vkt::written_by_transfer).oldLayout == VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
}

TEST_CASE("a target write no barrier can start from is named, not guessed at", "[runner]") {
    CHECK_THROWS_AS(to_copy({VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                             VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT}),
                    vkt::Error);
    CHECK_THROWS_AS(to_copy({VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE}),
                    vkt::Error);
}
