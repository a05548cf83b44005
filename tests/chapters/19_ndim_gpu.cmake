# Chapter 19: n-dimensional objects transformed and projected in the vertex
# shader.
#
# The golden picture: the default scene after 10 frames. It is chapter 18's
# scene (vkt::ndim::make_scene) at the same instant, transformed on the GPU
# instead of the CPU, so it must also match chapter 18's golden image: the
# test chapter.19_ndim_gpu.matches_18 compares the two.
vkt_chapter_test(chapter.19_ndim_gpu 19_ndim_gpu GOLDEN BLESS ARGS ${headless}
  EXPECT "19_ndim_gpu: default scene, n = 4, 2 objects, 128 lines per frame"
         "40 vertices and 256 indices on the GPU, 112 bytes of transforms per frame")
vkt_chapter_test(chapter.19_ndim_gpu.offscreen 19_ndim_gpu GOLDEN ARGS ${offscreen})
vkt_chapter_window_test(19_ndim_gpu)
add_test(NAME chapter.19_ndim_gpu.matches_18
  COMMAND vkt_chapter_check --exe $<TARGET_FILE:19_ndim_gpu> --out ${VKT_TEST_OUTPUT}
          --name chapter.19_ndim_gpu.matches_18 --golden ${VKT_GOLDEN_DIR}/18_ndim_cpu.png
          -- ${headless})
set_tests_properties(chapter.19_ndim_gpu.matches_18 PROPERTIES
  ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS chapter)

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
# within 1e-4 in clip units, every vertex written, the same ones clipped.
set(VKT_19_VERIFIED "verify cpu: .* max error [0-9.e-]+ \\(per-plane path\\), [0-9.e-]+ \\(chapter 18's matrix\\) in clip units, tolerance 1e-04; 0 visibility mismatches, 0 not written")
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

vkt_chapter_test(chapter.19_ndim_gpu.help 19_ndim_gpu EXIT 0 ARGS --help
  EXPECT "usage: 19_ndim_gpu" "--scene default\\|cube\\|many" "--dim N" "--verify CHECK")

# Bad input: a dimension outside 3..12, a scene that does not exist, --dim
# on the 4D scene, a --verify check that does not exist.
foreach(dim 0 2 13 100)
  vkt_chapter_test(bad_input.19_ndim_gpu.dim_${dim} 19_ndim_gpu EXIT 2 ARGS --scene cube --dim ${dim}
    EXPECT "--dim wants a whole number from 3 to 12, not '${dim}'")
endforeach()
vkt_chapter_test(bad_input.19_ndim_gpu.scene 19_ndim_gpu EXIT 2 ARGS --scene hypersphere
  EXPECT "--scene wants one of default, cube, many, not 'hypersphere'")
vkt_chapter_test(bad_input.19_ndim_gpu.dim_default_scene 19_ndim_gpu EXIT 1
  ARGS --headless --frames 1 --dim 5
  EXPECT "--dim 5: the default scene is 4-dimensional; use --scene cube or --scene many")
vkt_chapter_test(bad_input.19_ndim_gpu.verify 19_ndim_gpu EXIT 2 ARGS --verify gpu
  EXPECT "--verify wants one of cpu, not 'gpu'")
