# Chapter 15: bindless (descriptor indexing, buffer device address, one
# indirect multi-draw for 1025 objects).
#
# The sky is the clear colour, linear (0.30, 0.45, 0.65), stored sRGB-encoded
# as (149, 179, 211) in the top corners. By frame 10 every texture is
# resident (8 arrive per frame from frame 0), so the picture is the final one.
#
# Two lit floor pixels, worked out by hand from bindless.frag: the floor is
# slot 0's grey checker (sRGB 110 and 150, linear 0.1559 and 0.3050) with
# tint 1; its normal is +y, so lambert = dot(+y, normalize(0.4, 1, 0.3)) =
# 1 / sqrt(1.25) = 0.8944 and the light is 0.3 + 0.7 * 0.8944 = 0.9261.
# Dark square: 0.1559 * 0.9261 = 0.1444, sRGB 106; light square: 0.3050 *
# 0.9261 = 0.2825, sRGB 145. (Unlit they would be 110 and 150; with no
# ambient 88 and 121; lambert alone 104 and 143.) Both pixels lie in the middle of a checker square
# near the bottom, 7 x 7 pixels of one value around them.
set(VKT_15_PIXEL PIXEL 0,0,149,179,211 319,0,149,179,211 297,236,106,106,106 190,236,145,145,145)
vkt_chapter_test(chapter.15_bindless 15_bindless GOLDEN BLESS ${VKT_15_PIXEL} ARGS ${headless}
  EXPECT "15_bindless: 1025 objects \\(32 x 32 and the floor\\), 49 texture slots \\(48 textures and the loading one\\), one vkCmdDrawIndexedIndirect for all")
vkt_chapter_test(chapter.15_bindless.offscreen 15_bindless SAME_AS chapter.15_bindless ${VKT_15_PIXEL} ARGS ${offscreen})
vkt_chapter_window_test(15_bindless PIXEL 0,0,149,179,211 297,236,106,106,106)
# A loop of 1025 vkCmdDrawIndexed draws exactly what the one indirect call
# draws: the same golden image.
vkt_chapter_test(chapter.15_bindless.loop 15_bindless SAME_AS chapter.15_bindless ${VKT_15_PIXEL}
  ARGS ${headless} --draw loop EXPECT "one vkCmdDrawIndexed per object")
vkt_chapter_test(chapter.15_bindless.loop_offscreen 15_bindless SAME_AS chapter.15_bindless
  ARGS ${offscreen} --draw loop EXPECT "one vkCmdDrawIndexed per object")
# --benchmark reports the "draw" scope (median and p95).
vkt_chapter_test(chapter.15_bindless.benchmark 15_bindless
  ARGS --headless --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark
  EXPECT "\"gpu_scopes_ms\": \\{\"draw\": \\{\"min\": [0-9.]+, \"median\": [0-9.]+, \"p95\": [0-9.]+"
         "recording the draws took [0-9.]+ ms median, [0-9.]+ ms p95 on the CPU \\(5 frames\\)")
# A big grid (250 x 250 + the floor = 62,501 draws in one call) runs clean.
vkt_chapter_test(chapter.15_bindless.big_grid 15_bindless
  ARGS --headless --validation --frames 2 --size ${VKT_TEST_SIZE} --grid 250 --textures 96
  EXPECT "62501 objects \\(250 x 250 and the floor\\), 97 texture slots")
vkt_chapter_test(chapter.15_bindless.help 15_bindless EXIT 0 ARGS --help
  EXPECT "usage: 15_bindless" "--draw indirect\\|loop" "--grid N" "--textures N")

# Bad input: the command line.
vkt_chapter_test(bad_input.15_bindless.draw 15_bindless EXIT 2 ARGS --draw fast
  EXPECT "--draw wants one of indirect, loop, not 'fast'")
vkt_chapter_test(bad_input.15_bindless.grid 15_bindless EXIT 2 ARGS --grid 251
  EXPECT "--grid wants a whole number from 1 to 250, not '251'")
vkt_chapter_test(bad_input.15_bindless.textures 15_bindless EXIT 2 ARGS --textures 0
  EXPECT "--textures wants a whole number from 1 to 96, not '0'")
# Bad input: a device without a feature the chapter needs (hidden, since
# lavapipe has them all): one clear line naming it, exit status 1.
foreach(feature runtimeDescriptorArray shaderSampledImageArrayNonUniformIndexing
        descriptorBindingPartiallyBound descriptorBindingVariableDescriptorCount
        descriptorBindingSampledImageUpdateAfterBind descriptorBindingUpdateUnusedWhilePending
        bufferDeviceAddress multiDrawIndirect drawIndirectFirstInstance)
  vkt_chapter_test(bad_input.15_bindless.missing_${feature} 15_bindless EXIT 1
    ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=${feature}
    EXPECT "no Vulkan device can run this chapter; .* lacks the ${feature} feature")
endforeach()
