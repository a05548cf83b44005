# Chapter 19: n-dimensional objects transformed and projected in the vertex
# shader.
#
# The golden picture: the default scene after 10 frames. It is chapter 18's
# scene (vkt::ndim::make_scene) at the same instant, transformed on the GPU
# instead of the CPU, so it must also match chapter 18's golden image. With
# the edges in chapter 18's order (--edge-order axis) the lines are drawn in
# the same order too, and no channel differs by more than 1 (colours are
# bytes in 18, floats here): chapter.19_ndim_gpu.matches_18. In the default
# order, by vertex, a line drawn later covers another where two cross, so a
# few dozen crossing pixels differ: chapter.19_ndim_gpu.matches_18_by_vertex,
# within the usual tolerance.
vkt_chapter_test(chapter.19_ndim_gpu 19_ndim_gpu GOLDEN BLESS ARGS ${headless}
  EXPECT "19_ndim_gpu: default scene, n = 4, 2 objects, 128 lines per frame"
         "40 vertices and 256 indices on the GPU, 112 bytes of transforms per frame")
vkt_chapter_test(chapter.19_ndim_gpu.offscreen 19_ndim_gpu SAME_AS chapter.19_ndim_gpu ARGS ${offscreen})
vkt_chapter_window_test(19_ndim_gpu)
add_test(NAME chapter.19_ndim_gpu.matches_18
  COMMAND vkt_chapter_check --exe $<TARGET_FILE:19_ndim_gpu> --out ${VKT_TEST_OUTPUT}
          --name chapter.19_ndim_gpu.matches_18 --golden ${VKT_GOLDEN_DIR}/18_ndim_cpu.png
          -- ${headless} --edge-order axis)
add_test(NAME chapter.19_ndim_gpu.matches_18_by_vertex
  COMMAND vkt_chapter_check --exe $<TARGET_FILE:19_ndim_gpu> --out ${VKT_TEST_OUTPUT}
          --name chapter.19_ndim_gpu.matches_18_by_vertex
          --golden ${VKT_GOLDEN_DIR}/18_ndim_cpu.png -- ${headless})
set_tests_properties(chapter.19_ndim_gpu.matches_18 chapter.19_ndim_gpu.matches_18_by_vertex
  PROPERTIES ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS chapter)
# In the same order, tighter than the golden tolerance: at most 1 per channel
# (the checker still has to say PASS).
set_tests_properties(chapter.19_ndim_gpu.matches_18 PROPERTIES
  PASS_REGULAR_EXPRESSION "largest channel difference [01],.*PASS")

# Chapter 18's hand-worked pixels hold here too: the still 3-cube, its near
# square (x2 = +1, scaled by d / (d - 1) = 1.4058) on rows 55 and 184 and
# columns 95 and 224 in (233, 173, 147), its far square (scaled by 0.7760)
# on row 84 and columns 124 and 195 in (147, 156, 233); see
# 18_ndim_cpu.cmake for the arithmetic.
vkt_chapter_test(chapter.19_ndim_gpu.still_cube 19_ndim_gpu
  ARGS ${headless} --scene cube --dim 3 --motion still
  PIXEL 0,0,18,18,29 160,55,233,173,147 160,184,233,173,147 95,120,233,173,147
        224,120,233,173,147 160,84,147,156,233 124,120,147,156,233 195,120,147,156,233
        160,57,18,18,29 160,120,18,18,29
  EXPECT "cube scene, n = 3, 1 objects, 12 lines per frame, eye at 3.46")

# --verify cpu: the last frame's vertices captured from the vertex shader
# and compared with vkt::ndim's per-plane transform and chapter 18's matrix,
# within 1e-4 relative (to the half screen on the screen), every vertex
# written, the same ones clipped.
set(VKT_19_VERIFIED "verify cpu: .* max error [0-9.e-]+ \\(per-plane path\\), [0-9.e-]+ \\(chapter 18's matrix\\), relative, tolerance 1e-04; [0-9]+ clipped, 0 visibility mismatches, 0 not written")
vkt_chapter_test(chapter.19_ndim_gpu.verify_default 19_ndim_gpu ARGS ${headless} --verify cpu
  EXPECT "verify cpu: 40 vertices of 2 objects" "${VKT_19_VERIFIED}")
foreach(dim 4 8 12)
  vkt_chapter_test(chapter.19_ndim_gpu.verify_cube${dim} 19_ndim_gpu
    ARGS ${offscreen} --scene cube --dim ${dim} --verify cpu
    EXPECT "verify cpu: [0-9]+ vertices of 1 objects" "${VKT_19_VERIFIED}")
endforeach()
vkt_chapter_test(chapter.19_ndim_gpu.verify_many 19_ndim_gpu
  ARGS ${headless} --scene many --dim 4 --verify cpu
  EXPECT "verify cpu: 4000 vertices of 250 objects" "${VKT_19_VERIFIED}")
# 250 8-cubes, 256,000 lines: two frames are enough and keep the test short.
vkt_chapter_test(chapter.19_ndim_gpu.verify_many8 19_ndim_gpu
  ARGS --offscreen --validation --frames 2 --size ${VKT_TEST_SIZE} --scene many --dim 8
       --verify cpu --projection orthographic
  EXPECT "verify cpu: 64000 vertices of 250 objects" "${VKT_19_VERIFIED}")

# Clipping. With the eye at d = 1 instead of 3.46, the still 3-cube's near
# face (x2 = +1) lies exactly at the eye: its 4 vertices are clipped (the
# distance d - x2 is exactly 0, on the CPU and the GPU alike), and so are the
# 8 edges that touch them. What is left is the far face alone, scaled by
# d / (d + 1) = 0.5: 120 * 0.5 / 2.5981 = 23.09 pixels from the centre, on
# rows 96.91 and 143.09 and columns 136.91 and 183.09, which light rows 96
# and 143 and columns 136 and 183 (pixel centres within half a pixel), in
# the far face's colour (147, 156, 233). Where the near face and the
# edges towards it were, at (160, 55) and on the diagonal at (120, 80), and
# just inside the square, only the background remains.
vkt_chapter_test(chapter.19_ndim_gpu.clipped 19_ndim_gpu
  ARGS ${headless} --scene cube --dim 3 --motion still --eye 1
  PIXEL 160,96,147,156,233 160,143,147,156,233 136,120,147,156,233 183,120,147,156,233
        160,55,18,18,29 120,80,18,18,29 95,120,18,18,29 160,98,18,18,29 0,0,18,18,29)
vkt_chapter_test(chapter.19_ndim_gpu.verify_clipped 19_ndim_gpu
  ARGS ${headless} --scene cube --dim 3 --motion still --eye 1 --verify cpu
  EXPECT "verify cpu: 8 vertices of 1 objects.* 4 clipped, 0 visibility mismatches")
# Spinning, with the eye in the middle of a 5-cube: vertices come and go.
vkt_chapter_test(chapter.19_ndim_gpu.verify_clipped5 19_ndim_gpu
  ARGS ${offscreen} --scene cube --dim 5 --eye 1.5 --verify cpu
  EXPECT "verify cpu: 32 vertices of 1 objects.* [1-9][0-9]* clipped" "${VKT_19_VERIFIED}")

# The keys, in a real window (chapter 18's script: the same keys, the same
# lines on the terminal, each prefixed with the chapter's name).
if(XVFB_RUN AND XDOTOOL AND OPENBOX)
  add_test(NAME chapter.19_ndim_gpu.window_keys
    COMMAND ${XVFB_RUN} -a -s "-screen 0 800x600x24"
            ${CMAKE_CURRENT_SOURCE_DIR}/window_ndim_keys.sh $<TARGET_FILE:19_ndim_gpu>
            ${VKT_TEST_OUTPUT}/19_ndim_gpu.window_keys "19 - ndim_gpu")
  set_tests_properties(chapter.19_ndim_gpu.window_keys PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
endif()

# --benchmark also counts the vertex shader's invocations (a pipeline
# statistics query) against the indices and vertices drawn.
vkt_chapter_test(chapter.19_ndim_gpu.benchmark 19_ndim_gpu
  ARGS --headless --validation --frames 4 --size ${VKT_TEST_SIZE} --benchmark --scene cube --dim 8
  EXPECT "\"gpu_scopes_ms\": \\{\"raster\": \\{\"min\": [0-9.]+"
         "vertex shader invocations per frame: \\{\"min\": [0-9.]+.*, for 2048 indices and 256 vertices")

vkt_chapter_test(chapter.19_ndim_gpu.help 19_ndim_gpu EXIT 0 ARGS --help
  EXPECT "usage: 19_ndim_gpu" "--scene default\\|cube\\|many" "--dim N" "--verify CHECK")

# Bad input: a dimension outside 3..12, a scene that does not exist, --dim
# on the 4D scene, a --verify check that does not exist, an eye at 0.
foreach(dim 0 2 13 100)
  vkt_chapter_test(bad_input.19_ndim_gpu.dim_${dim} 19_ndim_gpu EXIT 2 ARGS --scene cube --dim ${dim}
    EXPECT "--dim wants a whole number from 3 to 12, not '${dim}'")
endforeach()
vkt_chapter_test(bad_input.19_ndim_gpu.scene 19_ndim_gpu EXIT 2 ARGS --scene hypersphere
  EXPECT "--scene wants one of default, cube, many, not 'hypersphere'")
vkt_chapter_test(bad_input.19_ndim_gpu.dim_default_scene 19_ndim_gpu EXIT 2
  ARGS --headless --frames 1 --dim 5
  EXPECT "--dim 5: the default scene is 4-dimensional; use --scene cube or --scene many")
vkt_chapter_test(bad_input.19_ndim_gpu.verify 19_ndim_gpu EXIT 2 ARGS --verify gpu
  EXPECT "--verify wants one of cpu, not 'gpu'")
vkt_chapter_test(bad_input.19_ndim_gpu.eye 19_ndim_gpu EXIT 2 ARGS --eye 0
  EXPECT "--eye wants a number from 0.1 to 1000, not '0'")
