# Chapter 17: tiled deferred shading. Chapter 16's scene under 1,024 moving
# lights: a compute pass culls the lights per 16 x 16 tile, and the lighting
# reads only its tile's list (--shade fragment), or one dispatch culls and
# shades (--shade compute). Each tile tests the lights binned to it (--cull
# binned, the default) or every light (--cull tiled).
#
# Hand-worked pixels: the top corners show no geometry, so both paths write
# the background (0.02, 0.02, 0.04), stored sRGB-encoded as (39, 39, 56).
# And two pixels of bare floor under the 1,024 lights at frame 9, worked out
# on the CPU (tests/unit/test_deferred.cpp, "chapters 16 and 17: lit floor
# pixels"): (63, 153) is (207, 174, 187), (117, 192) is (180, 163, 155).
set(VKT_17_PIXEL PIXEL 0,0,39,39,56 319,0,39,39,56 63,153,207,174,187,2 117,192,180,163,155,2)
vkt_chapter_test(chapter.17_tiled_deferred 17_tiled_deferred GOLDEN BLESS ${VKT_17_PIXEL}
  ARGS ${headless} EXPECT "17_tiled_deferred: 1024 lights, shade fragment, view lit, cull binned"
  "tiles overflowed: 0" "frames that dropped candidates: 0")
vkt_chapter_test(chapter.17_tiled_deferred.offscreen 17_tiled_deferred SAME_AS chapter.17_tiled_deferred ${VKT_17_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(17_tiled_deferred PIXEL 0,0,39,39,56)
# The compute path: the same picture, to the bit (compared with the run
# above); in a window too, where the blit's target is then copied to the
# swapchain image.
vkt_chapter_test(chapter.17_tiled_deferred.compute 17_tiled_deferred SAME_AS chapter.17_tiled_deferred ${VKT_17_PIXEL}
  ARGS ${headless} --shade compute EXPECT "shade compute")
# --shade lists with the default --cull binned: the same picture too
# (the cull_tiled_* tests below run every --shade with --cull tiled).
vkt_chapter_test(chapter.17_tiled_deferred.lists 17_tiled_deferred SAME_AS chapter.17_tiled_deferred ${VKT_17_PIXEL}
  ARGS ${headless} --shade lists EXPECT "shade lists, view lit, cull binned")
if(XVFB_RUN)
  set(test chapter.17_tiled_deferred.window_compute)
  add_test(NAME ${test}
    COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24"
            $<TARGET_FILE:vkt_chapter_check> --exe $<TARGET_FILE:17_tiled_deferred>
            --out ${VKT_TEST_OUTPUT} --name ${test}
            --same-as ${VKT_TEST_OUTPUT}/chapter.17_tiled_deferred.png --pixel 0,0,39,39,56
            --expect "17_tiled_deferred: .*, window B8G8R8A8_" --expect "shade compute" --
            --validation --frames ${VKT_TEST_FRAMES} --size ${VKT_TEST_SIZE} --shade compute)
  set_tests_properties(${test} PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
  vkt_same_picture(${test} chapter.17_tiled_deferred)
endif()

# --cull tiled, every tile testing every light: the same picture, both ways.
foreach(shade fragment compute lists)
  vkt_chapter_test(chapter.17_tiled_deferred.cull_tiled_${shade} 17_tiled_deferred
    SAME_AS chapter.17_tiled_deferred ${VKT_17_PIXEL} ARGS ${headless} --cull tiled --shade ${shade}
    EXPECT "shade ${shade}, view lit, cull tiled")
endforeach()

# With chapter 16's 32 lights the scene is chapter 16's: both tiled paths
# against chapter 16's golden image (the golden tests' tolerance).
foreach(shade fragment compute lists)
  set(test chapter.17_tiled_deferred.matches_16_${shade})
  add_test(NAME ${test} COMMAND vkt_chapter_check --exe $<TARGET_FILE:17_tiled_deferred>
    --out ${VKT_TEST_OUTPUT} --name ${test} --golden ${VKT_GOLDEN_DIR}/16_deferred.png
    --pixel 0,0,39,39,56 --expect "32 lights, shade ${shade}"
    -- ${headless} --lights 32 --shade ${shade})
  set_tests_properties(${test} PROPERTIES ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}"
    LABELS "chapter")
endforeach()

# The heat map: lights per tile, one golden image for all three paths (the
# fragment path's run owns it; the others must equal that run to the bit).
# Hand-worked pixel: the top-left tile holds no geometry, so it kept 0
# lights: the ramp's (0, 0, 0.5), shown 75% over a black albedo as
# (0, 0, 0.375), sRGB-encoded (0, 0, 164); its border pixel (0, 0) is half
# that, 0.1875, encoded 121.
set(VKT_17_HEAT PIXEL 8,8,0,0,164 0,0,0,0,121)
vkt_chapter_test(chapter.17_tiled_deferred.view_heat_fragment 17_tiled_deferred
  GOLDEN_FILE 17_tiled_deferred_heat.png LABELS bless ${VKT_17_HEAT}
  ARGS ${headless} --view heat --shade fragment EXPECT "view heat")
foreach(shade compute lists)
  vkt_chapter_test(chapter.17_tiled_deferred.view_heat_${shade} 17_tiled_deferred
    SAME_AS chapter.17_tiled_deferred.view_heat_fragment ${VKT_17_HEAT}
    ARGS ${headless} --view heat --shade ${shade} EXPECT "view heat")
endforeach()

# --verify brute: the last frame again, into float images: chapter 16's
# brute-force lighting pass (every light at every pixel), the tiled fragment
# pass and the tiled compute pass, read back and compared pairwise: the
# largest difference of any channel of any pixel at most 1e-4 (relative above
# 1), and no tile's list overflowed. Also at a size that is not a multiple of
# the tile (partial tiles on the right and bottom), and with 16,384 lights.
vkt_chapter_test(chapter.17_tiled_deferred.verify_brute 17_tiled_deferred
  ARGS ${headless} --verify brute
  EXPECT "verify motion: 1024 lights at t = [0-9.]+, largest position difference from the CPU"
  "verify brute: tiled fragment vs brute force, largest difference"
  "verify brute: tiled compute vs brute force" "tiles overflowed 0")
vkt_chapter_test(chapter.17_tiled_deferred.verify_brute_odd_size 17_tiled_deferred
  ARGS --offscreen --validation --frames 3 --size 250x130 --verify brute --shade compute
  EXPECT "250x130 pixels")
vkt_chapter_test(chapter.17_tiled_deferred.verify_brute_many 17_tiled_deferred
  ARGS --offscreen --no-validation --frames 1 --size ${VKT_TEST_SIZE} --verify brute
  --lights 16384 EXPECT "16384 lights")

# --verify bins: the frame culled both ways from one G-buffer; the tiles'
# lists must hold the same lights (compared as sets, tile by tile; a list that
# overflowed by its count), and the pictures of both shading paths agree
# within 1e-4. At 320x240 with validation, at a size with partial tiles, and
# with many lights; a million at 256x144 overflows lists (its counts are
# compared), and shows the binning itself at full size.
vkt_chapter_test(chapter.17_tiled_deferred.verify_bins 17_tiled_deferred
  ARGS ${headless} --verify bins
  EXPECT "verify bins: 300 tiles, [0-9]+ lights kept in all .*; lists that differ: 0"
  "binned vs tiled, shade fragment, largest difference" "binned vs tiled, shade compute")
vkt_chapter_test(chapter.17_tiled_deferred.verify_bins_odd_size 17_tiled_deferred
  ARGS --offscreen --validation --frames 2 --size 250x130 --verify bins --lights 4096
  EXPECT "144 tiles, .*250x130 pixels\\); lists that differ: 0")
vkt_chapter_test(chapter.17_tiled_deferred.verify_bins_many 17_tiled_deferred
  ARGS --offscreen --no-validation --frames 1 --size ${VKT_TEST_SIZE} --verify bins
  --lights 65536 EXPECT "65536 lights, .*lists that differ: 0")
vkt_chapter_test(chapter.17_tiled_deferred.verify_bins_million 17_tiled_deferred
  ARGS --offscreen --no-validation --frames 1 --size 256x144 --verify bins
  --lights 1048576 EXPECT "verify motion: 1048576 lights"
  "1048576 lights, .*lists that differ: 0; overflowed \\(counts compared\\): [0-9]+")
# Binning's own overflow: a budget too small for the bins. The fill drops what
# does not fit; the run says so, the bins grow for the next frames, and
# --verify bins refuses a frame that dropped candidates.
vkt_chapter_test(chapter.17_tiled_deferred.bins_grow 17_tiled_deferred
  ARGS --offscreen --validation --frames 4 --size ${VKT_TEST_SIZE} --bin-budget 1000
  EXPECT "the bins needed [0-9]+ candidates: budget now [0-9]+"
  "frames that dropped candidates: [1-9]")
vkt_chapter_test(chapter.17_tiled_deferred.bins_overflow_fails_verify 17_tiled_deferred EXIT 1
  ARGS --offscreen --no-validation --frames 1 --size ${VKT_TEST_SIZE} --bin-budget 1000
  --verify bins EXPECT "--verify bins: the bins needed [0-9]+ candidates, above their budget of 1000")

# Overflow is counted, never silent: at 64x48 a tile covers a large part of
# the floor, and 65,536 lights overflow some lists. The run reports it; the
# check refuses the picture.
vkt_chapter_test(chapter.17_tiled_deferred.overflow_reported 17_tiled_deferred
  ARGS --offscreen --validation --frames 2 --size 64x48 --lights 65536
  EXPECT "65536 lights" "a list holds 2048\\); tiles overflowed: [1-9]")
vkt_chapter_test(chapter.17_tiled_deferred.overflow_fails_verify 17_tiled_deferred EXIT 1
  ARGS --offscreen --no-validation --frames 1 --size 64x48 --lights 65536 --verify brute
  EXPECT "--verify brute: [0-9]+ tiles had more than 2048 lights; their lists dropped lights")

# --benchmark times the passes as named GPU scopes.
vkt_chapter_test(chapter.17_tiled_deferred.benchmark 17_tiled_deferred
  ARGS --offscreen --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark
  EXPECT "\"gpu_scopes_ms\": \\{\"move\": \\{\"min\": [0-9.]+.*\"gbuffer\": \\{.*\"bin\": \\{.*\"cull\": \\{.*\"lighting\": \\{")
vkt_chapter_test(chapter.17_tiled_deferred.benchmark_compute 17_tiled_deferred
  ARGS --offscreen --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark
  --shade compute
  EXPECT "\"gpu_scopes_ms\": \\{\"move\": \\{\"min\": [0-9.]+.*\"gbuffer\": \\{.*\"bin\": \\{.*\"shade\": \\{.*\"copy\": \\{")
vkt_chapter_test(chapter.17_tiled_deferred.benchmark_tiled 17_tiled_deferred
  ARGS --offscreen --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark
  --shade compute --cull tiled
  EXPECT "\"gpu_scopes_ms\": \\{\"move\": \\{[^}]*\\}, \"gbuffer\": \\{\"min\": [0-9.]+, [^}]*\\}, \"shade\": \\{.*\"copy\": \\{")
vkt_chapter_test(chapter.17_tiled_deferred.help 17_tiled_deferred EXIT 0 ARGS --help
  EXPECT "usage: 17_tiled_deferred" "--shade PASS" "--cull HOW" "--view VIEW" "--lights N"
  "--bin-budget N" "--verify CHECK")

# Bad input: one clear line and a non-zero exit status. The most lights is
# 1,048,576 (32 MiB of lights per frame in flight).
vkt_chapter_test(bad_input.17_tiled_deferred.no_lights 17_tiled_deferred EXIT 2 ARGS --lights 0
  EXPECT "--lights wants a whole number from 1 to 1048576, not '0'")
vkt_chapter_test(bad_input.17_tiled_deferred.too_many_lights 17_tiled_deferred EXIT 2
  ARGS --lights 1048577 EXPECT "--lights wants a whole number from 1 to 1048576, not '1048577'")
vkt_chapter_test(bad_input.17_tiled_deferred.bad_cull 17_tiled_deferred EXIT 2
  ARGS --cull clustered EXPECT "--cull wants one of binned, tiled, not 'clustered'")
vkt_chapter_test(bad_input.17_tiled_deferred.bad_shade 17_tiled_deferred EXIT 2
  ARGS --shade raster EXPECT "--shade wants one of fragment, compute, lists, not 'raster'")
vkt_chapter_test(bad_input.17_tiled_deferred.bad_view 17_tiled_deferred EXIT 2
  ARGS --view normal EXPECT "--view wants one of lit, heat, not 'normal'")
vkt_chapter_test(bad_input.17_tiled_deferred.bad_verify 17_tiled_deferred EXIT 2
  ARGS --verify cpu EXPECT "--verify wants one of brute, bins, not 'cpu'")
# The required features: a device without one is refused with its name.
foreach(feature maintenance4 separateDepthStencilLayouts)
  vkt_chapter_test(bad_input.17_tiled_deferred.missing_${feature} 17_tiled_deferred EXIT 1
    ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=${feature}
    EXPECT "no Vulkan device can run this chapter; .* lacks the ${feature} feature")
endforeach()
