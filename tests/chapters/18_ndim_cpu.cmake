# Chapter 18: n-dimensional objects transformed and projected on the CPU.
#
# The golden picture: the default scene (a tesseract and a 24-cell) after 10
# frames; headless, the angles are start + spin * (frame index / 60), so the
# picture is the same on every run, in a window too (no keys under --frames).
vkt_chapter_test(chapter.18_ndim_cpu 18_ndim_cpu GOLDEN BLESS ARGS ${headless}
  EXPECT "18_ndim_cpu: default scene, n = 4, 2 objects, 128 lines per frame")
vkt_chapter_test(chapter.18_ndim_cpu.offscreen 18_ndim_cpu SAME_AS chapter.18_ndim_cpu ARGS ${offscreen})
vkt_chapter_window_test(18_ndim_cpu)
# Building the model matrix row by row gives the same matrix (to rounding),
# so the same picture.
vkt_chapter_test(chapter.18_ndim_cpu.rows 18_ndim_cpu GOLDEN ARGS ${headless} --matrix rows)

# Hand-worked pixels: the 3-cube (s = 1) standing still, every angle 0. Its
# radius is r = sqrt(3), the eye at d = 2 r sqrt(3 - 2) = 3.4641 on axis 2,
# the view's half height 1.5 r = 2.5981. The near face (x2 = +1) is scaled by
# d / (d - 1) = 1.4058, the far one (x2 = -1) by d / (d + 1) = 0.7760; at
# 320x240 that is 120 * 1.4058 / 2.5981 = 64.93 pixels and 35.84 pixels from
# the centre (160, 120): the near square's edges lie on rows 55.07 and 184.93
# and columns 95.07 and 224.93, the far square's on row 84.16 and columns
# 124.16 and 195.84. Colours: depth t = x2 / r = +-0.5774, so the near face
# is linear (0.810, 0.418, 0.290), bytes (207, 107, 74), stored sRGB-encoded
# as (233, 173, 147); the far face (0.290, 0.332, 0.810) -> (74, 85, 207) ->
# (147, 156, 233); the background (0.006, 0.006, 0.012) -> (18, 18, 29).
set(VKT_18_STILL ${VKT_TEST_OUTPUT}/chapter.18_ndim_cpu.still_cube.png)
vkt_chapter_test(chapter.18_ndim_cpu.still_cube 18_ndim_cpu
  ARGS ${headless} --scene cube --dim 3 --motion still --screenshot ${VKT_18_STILL}
  EXPECT "cube scene, n = 3, 1 objects, 12 lines per frame, eye at 3.46")
add_test(NAME chapter.18_ndim_cpu.still_cube_pixels
  COMMAND vkt_chapter_check --png ${VKT_18_STILL}
          --pixel 0,0,18,18,29 --pixel 160,55,233,173,147 --pixel 160,184,233,173,147
          --pixel 95,120,233,173,147 --pixel 224,120,233,173,147
          --pixel 160,84,147,156,233 --pixel 124,120,147,156,233 --pixel 195,120,147,156,233
          --pixel 160,57,18,18,29 --pixel 160,120,18,18,29)
set_tests_properties(chapter.18_ndim_cpu.still_cube PROPERTIES FIXTURES_SETUP ndim18_still)
set_tests_properties(chapter.18_ndim_cpu.still_cube_pixels PROPERTIES
  FIXTURES_REQUIRED ndim18_still LABELS chapter)

# The other scenes run clean (no golden: the page shows them).
vkt_chapter_test(chapter.18_ndim_cpu.cube8 18_ndim_cpu ARGS ${headless} --scene cube --dim 8
  EXPECT "cube scene, n = 8, 1 objects, 1024 lines per frame")
vkt_chapter_test(chapter.18_ndim_cpu.many 18_ndim_cpu ARGS ${headless} --scene many --dim 5
  --projection orthographic EXPECT "many scene, n = 5, 250 objects, 20000 lines per frame")
vkt_chapter_test(chapter.18_ndim_cpu.help 18_ndim_cpu EXIT 0 ARGS --help
  EXPECT "usage: 18_ndim_cpu" "--scene default\\|cube\\|many" "--dim N")

# Bad input: a dimension outside 3..12 (below 3 there is nothing to project;
# above 12 the 250-cube scene needs more than 141 MiB of line vertices per
# frame in flight), a scene that does not exist, --dim on the 4D scene.
foreach(dim 0 1 2 13 100)
  vkt_chapter_test(bad_input.18_ndim_cpu.dim_${dim} 18_ndim_cpu EXIT 2 ARGS --scene cube --dim ${dim}
    EXPECT "--dim wants a whole number from 3 to 12, not '${dim}'")
endforeach()
vkt_chapter_test(bad_input.18_ndim_cpu.scene 18_ndim_cpu EXIT 2 ARGS --scene hypersphere
  EXPECT "--scene wants one of default, cube, many, not 'hypersphere'")
# Contradictory flags are a bad command line (status 2), found before any
# Vulkan object exists: the usage line follows the message.
vkt_chapter_test(bad_input.18_ndim_cpu.dim_default_scene 18_ndim_cpu EXIT 2
  ARGS --headless --frames 1 --dim 5
  EXPECT "--dim 5: the default scene is 4-dimensional; use --scene cube or --scene many"
         "usage: 18_ndim_cpu")

# The keys, in a real window driven by events (window_ndim_keys.sh): a digit
# turns its plane, an F key moves along its axis, Shift reverses, R resets,
# O and Space switch the projection and pause the spin, Escape quits.
if(XVFB_RUN AND XDOTOOL AND OPENBOX)
  add_test(NAME chapter.18_ndim_cpu.window_keys
    COMMAND ${XVFB_RUN} -a -s "-screen 0 800x600x24"
            ${CMAKE_CURRENT_SOURCE_DIR}/window_ndim_keys.sh $<TARGET_FILE:18_ndim_cpu>
            ${VKT_TEST_OUTPUT} "18 - ndim_cpu")
  set_tests_properties(chapter.18_ndim_cpu.window_keys PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
endif()
