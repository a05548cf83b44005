// The runner's layout contract (vkt/frame/runner.hpp): a chapter says the
// layout it leaves its target in, and the runner's next barrier waits for the
// stage and access that layout implies.
#include "vkt/core/check.hpp"
#include "vkt/frame/runner.hpp"

#include <catch2/catch_test_macros.hpp>

TEST_CASE("the layout a chapter leaves its target in names its last write", "[runner]") {
    const vkt::LastWrite colour = vkt::last_write_in(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    CHECK(colour.stage == VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    CHECK(colour.access == VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    // A compute pass that stored the pixels (chapter 20's resolve).
    const vkt::LastWrite stored = vkt::last_write_in(VK_IMAGE_LAYOUT_GENERAL);
    CHECK(stored.stage == VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    CHECK(stored.access == VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    // A copy or a blit into it (chapter 20's compute rasteriser without a
    // storage view, chapter 17's compute shading): any transfer stage.
    const vkt::LastWrite copied = vkt::last_write_in(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    CHECK(copied.stage == VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT);
    CHECK(copied.access == VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // Any other layout is a chapter's mistake, named rather than guessed at.
    CHECK_THROWS_AS(vkt::last_write_in(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), vkt::Error);
    CHECK_THROWS_AS(vkt::last_write_in(VK_IMAGE_LAYOUT_UNDEFINED), vkt::Error);
}
