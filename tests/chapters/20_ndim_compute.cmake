# Chapter 20: n-dimensional objects transformed and projected by a compute
# pass, the lines drawn by the graphics pipeline or by a compute rasteriser.
#
# The golden picture: the default scene (a tesseract and a 24-cell) after 10
# frames, the same poses as chapter 18 (headless time is frame index / 60).
# The graphics pipeline's lines (--raster graphics; the default, auto, picks
# the compute rasteriser on lavapipe, tested below).
vkt_chapter_test(chapter.20_ndim_compute 20_ndim_compute GOLDEN BLESS
  PIXEL 0,0,18,18,29 319,239,18,18,29 ARGS ${headless} --raster graphics
  EXPECT "20_ndim_compute: default scene, n = 4, 2 objects, 40 vertices, 128 lines per frame, raster graphics")
vkt_chapter_test(chapter.20_ndim_compute.offscreen 20_ndim_compute
  SAME_AS chapter.20_ndim_compute ARGS ${offscreen} --raster graphics)
vkt_chapter_window_test(20_ndim_compute ARGS --raster graphics)
# The compute rasteriser's picture, with its own golden image (the checker is
# called directly to name it, as chapter 16 does for its debug views). Its
# lines step one pixel per column or row like the hardware's, but the pixels
# chosen differ here and there, and where lines cross the nearer one wins.
# Offscreen, the same picture as headless, to the bit.
vkt_chapter_test(chapter.20_ndim_compute.compute_raster.headless 20_ndim_compute
  GOLDEN_FILE 20_ndim_compute_compute_raster.png LABELS bless
  PIXEL 0,0,18,18,29 319,239,18,18,29 EXPECT "raster compute" ARGS ${headless} --raster compute)
vkt_chapter_test(chapter.20_ndim_compute.compute_raster.offscreen 20_ndim_compute
  SAME_AS chapter.20_ndim_compute.compute_raster.headless PIXEL 0,0,18,18,29 319,239,18,18,29
  EXPECT "raster compute" ARGS ${offscreen} --raster compute)

# --raster auto, the default (tuning.hpp): on a CPU device the compute
# rasteriser, whatever the scene; its picture exactly (the same as the
# compute rasteriser's run below, drawn by this build on this machine).
foreach(scene default many)
  set(test chapter.20_ndim_compute.auto_${scene})
  set(golden)
  if(scene STREQUAL "default")
    set(golden --same-as ${VKT_TEST_OUTPUT}/chapter.20_ndim_compute.compute_raster.headless.png)
  endif()
  add_test(NAME ${test} COMMAND vkt_chapter_check --exe $<TARGET_FILE:20_ndim_compute>
    --out ${VKT_TEST_OUTPUT} --name ${test} ${golden}
    --expect "${scene} scene, .* lines per frame, raster compute \\(auto\\)"
    -- ${headless} --scene ${scene})
  set_tests_properties(${test} PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS chapter)
  if(golden)
    vkt_same_picture(${test} chapter.20_ndim_compute.compute_raster.headless)
  endif()
endforeach()

# The same picture as chapter 18's golden image (within vkt::Tolerance): the
# compute pass and one indexed draw give what the CPU path gave. Not labelled
# bless: blessing never rewrites chapter 18's image from here.
add_test(NAME chapter.20_ndim_compute.same_as_18 COMMAND vkt_chapter_check
  --exe $<TARGET_FILE:20_ndim_compute> --out ${VKT_TEST_OUTPUT} --name chapter.20_ndim_compute.same_as_18
  --golden ${VKT_GOLDEN_DIR}/18_ndim_cpu.png -- ${headless} --raster graphics)
set_tests_properties(chapter.20_ndim_compute.same_as_18 PROPERTIES
  ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS chapter)

# --raster binned: the compute rasteriser tile by tile (binned_raster.hpp). It
# must draw the compute rasteriser's picture exactly, so it is checked against
# that run's picture with no tolerance at all (--same-as), headless and
# offscreen.
foreach(mode headless offscreen)
  vkt_chapter_test(chapter.20_ndim_compute.binned.${mode} 20_ndim_compute
    SAME_AS chapter.20_ndim_compute.compute_raster.headless
    EXPECT "raster binned" ARGS ${${mode}} --raster binned)
endforeach()
# --to-target store: the compute pass that stores the pixel buffer into the
# colour target through the runner's _UNORM storage view of it
# (resolve_pass.hpp), which a CPU device leaves out by default. The picture
# must not change by a bit: headless (a B8G8R8A8_UNORM view, the bytes
# swizzled) and offscreen (R8G8B8A8_UNORM), both rasterisers; the --benchmark
# scopes say the resolve ran. The binned runs end with --verify raster, whose
# frame then fills the buffer again (the resolve had left it clean) and
# still gives the same picture.
foreach(raster compute binned)
  foreach(mode headless offscreen)
    set(test chapter.20_ndim_compute.store_${raster}.${mode})
    set(verify)
    if(raster STREQUAL "binned")
      set(verify --verify raster)
    endif()
    vkt_chapter_test(${test} 20_ndim_compute
      SAME_AS chapter.20_ndim_compute.compute_raster.headless
      EXPECT "raster ${raster}" "\"resolve\": \\{"
      ARGS ${${mode}} --raster ${raster} --to-target store --benchmark ${verify})
  endforeach()
endforeach()
# --same-as can fail: chapter 19's picture is within the tolerance of chapter
# 18's (RMSE 0.9) but not equal to it, and the checker must say so (a crash,
# a bad flag or a validation message would fail with another message).
vkt_chapter_test(chapter.20_ndim_compute.exact_catches_a_difference 19_ndim_gpu
  SAME_AS chapter.18_ndim_cpu ARGS ${headless})
set_tests_properties(chapter.20_ndim_compute.exact_catches_a_difference PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*chapter\\.18_ndim_cpu\\.png")
# --verify raster: on the last frame both compute rasterisers draw the frame
# and every word of the two pixel buffers is compared, in scenes the golden
# image does not show: many objects, many tiles each (one 12-cube; long
# lines of a 4-cube at 1280x720), tiles cut by the image's edge (333x211),
# orthographic projection. Synchronisation validation on, as everywhere.
set(VKT_20_SAME "verify: binned against compute, [0-9x]+ pixels \\([0-9]+ lit by lines\\), 0 differ")
# The first also stores each frame into the target (--to-target store) at
# a size that cuts the resolve pass's 16 x 16 workgroups.
foreach(case "many;6;333x211;store" "cube;12;640x480;auto" "cube;4;1280x720;auto"
        "many;8;640x360;auto")
  list(GET case 0 scene)
  list(GET case 1 dim)
  list(GET case 2 size)
  list(GET case 3 to_target)
  vkt_chapter_test(chapter.20_ndim_compute.verify_binned_${scene}${dim} 20_ndim_compute
    ARGS --headless --validation --frames 3 --size ${size} --scene ${scene} --dim ${dim}
         --raster binned --verify raster --to-target ${to_target}
    EXPECT "${VKT_20_SAME}")
endforeach()
vkt_chapter_test(chapter.20_ndim_compute.verify_binned_ortho 20_ndim_compute
  ARGS ${offscreen} --scene many --dim 5 --projection orthographic --raster binned --verify raster
  EXPECT "${VKT_20_SAME}")

# Hand-worked pixels, chapter 18's still 3-cube (its tests file has the
# arithmetic): the near square's edges on rows 55 and 184 and columns 95 and
# 224 in (233, 173, 147), the far square's on row 84 and columns 124 and 195
# in (147, 156, 233), background (18, 18, 29). All three rasterisers, within
# 2 levels: the compute ones quantise the depth colour to 255 levels.
foreach(raster graphics compute binned)
  set(png ${VKT_TEST_OUTPUT}/chapter.20_ndim_compute.still_cube_${raster}.png)
  vkt_chapter_test(chapter.20_ndim_compute.still_cube_${raster} 20_ndim_compute
    ARGS ${headless} --scene cube --dim 3 --motion still --raster ${raster} --screenshot ${png}
    EXPECT "cube scene, n = 3, 1 objects, 8 vertices, 12 lines per frame, raster ${raster}")
  add_test(NAME chapter.20_ndim_compute.still_cube_${raster}_pixels
    COMMAND vkt_chapter_check --png ${png}
            --pixel 0,0,18,18,29,2 --pixel 160,55,233,173,147,2 --pixel 160,184,233,173,147,2
            --pixel 95,120,233,173,147,2 --pixel 224,120,233,173,147,2
            --pixel 160,84,147,156,233,2 --pixel 124,120,147,156,233,2
            --pixel 195,120,147,156,233,2 --pixel 160,57,18,18,29,2 --pixel 160,120,18,18,29,2)
  set_tests_properties(chapter.20_ndim_compute.still_cube_${raster} PROPERTIES
    FIXTURES_SETUP ndim20_still_${raster})
  set_tests_properties(chapter.20_ndim_compute.still_cube_${raster}_pixels PROPERTIES
    FIXTURES_REQUIRED ndim20_still_${raster} LABELS chapter)
endforeach()

# --verify cpu: the transform pass's projected vertices read back and
# compared with vkt::ndim (per-plane transform_point, project_to_2d): at most
# 1e-4 clip units in position (0.1 pixel across 1920) and 1e-4 in depth.
set(VKT_20_VERIFY "verify: [0-9]+ vertices .*tolerance 0.0001, 0 visibility mismatches")
vkt_chapter_test(chapter.20_ndim_compute.verify 20_ndim_compute ARGS ${headless} --verify cpu
  EXPECT "verify: 40 vertices" "${VKT_20_VERIFY}")
foreach(dim 4 8 12)
  vkt_chapter_test(chapter.20_ndim_compute.verify_cube${dim} 20_ndim_compute
    ARGS ${offscreen} --scene cube --dim ${dim} --verify cpu --raster compute
    EXPECT "cube scene, n = ${dim}, 1 objects" "${VKT_20_VERIFY}")
endforeach()
vkt_chapter_test(chapter.20_ndim_compute.verify_many 20_ndim_compute
  ARGS ${offscreen} --scene many --dim 6 --verify cpu
  EXPECT "many scene, n = 6, 250 objects, 16000 vertices, 48000 lines per frame" "verify: 16000 vertices"
  "${VKT_20_VERIFY}")
# --verify cpu with --raster binned: its transform pass also writes the
# boxes (set 2), which the check must bind too.
vkt_chapter_test(chapter.20_ndim_compute.verify_binned 20_ndim_compute
  ARGS ${offscreen} --scene many --dim 6 --verify cpu --raster binned
  EXPECT "raster binned" "${VKT_20_VERIFY}")
vkt_chapter_test(chapter.20_ndim_compute.verify_ortho 20_ndim_compute
  ARGS ${headless} --scene many --dim 5 --projection orthographic --verify cpu --raster compute
  EXPECT "${VKT_20_VERIFY}")
vkt_chapter_test(chapter.20_ndim_compute.help 20_ndim_compute EXIT 0 ARGS --help
  EXPECT "usage: 20_ndim_compute" "--raster auto\\|graphics\\|compute\\|binned" "--verify cpu\\|raster")

# Bad input: a dimension outside 3..12, a scene or a rasteriser that does
# not exist, --dim on the 4D scene, a target too big for the pixel buffer.
foreach(dim 2 13)
  vkt_chapter_test(bad_input.20_ndim_compute.dim_${dim} 20_ndim_compute EXIT 2
    ARGS --scene cube --dim ${dim} EXPECT "--dim wants a whole number from 3 to 12, not '${dim}'")
endforeach()
vkt_chapter_test(bad_input.20_ndim_compute.scene 20_ndim_compute EXIT 2 ARGS --scene hypersphere
  EXPECT "--scene wants one of default, cube, many, not 'hypersphere'")
vkt_chapter_test(bad_input.20_ndim_compute.raster 20_ndim_compute EXIT 2 ARGS --raster magic
  EXPECT "--raster wants one of auto, graphics, compute, binned, not 'magic'")
vkt_chapter_test(bad_input.20_ndim_compute.verify_raster_alone 20_ndim_compute EXIT 2
  ARGS --headless --frames 1 --verify raster
  EXPECT "--verify raster compares --raster binned with --raster compute: use it with --raster binned")
vkt_chapter_test(bad_input.20_ndim_compute.dim_default_scene 20_ndim_compute EXIT 2
  ARGS --headless --frames 1 --dim 5
  EXPECT "--dim 5: the default scene is 4-dimensional; use --scene cube or --scene many")
# A target whose pixel buffer does not fit in one storage-buffer range
# (lavapipe's is 128 MiB, 134217728 bytes; 8192x4097 pixels need 32768 more).
vkt_chapter_test(bad_input.20_ndim_compute.pixel_buffer_range 20_ndim_compute EXIT 1
  ARGS --offscreen --frames 1 --size 8192x4097 --raster compute
  EXPECT "8192x4097 needs a pixel buffer of 134250496 bytes, more than this device's maxStorageBufferRange \\(134217728\\)")
# A device without subgroup arithmetic in compute shaders, which the binned
# rasteriser's transform pass needs (lavapipe has it; the test hides it).
vkt_chapter_test(bad_input.20_ndim_compute.no_subgroup_arithmetic 20_ndim_compute EXIT 1
  ARGS --headless --frames 1 --raster binned
  ENV VKT_HIDE_FEATURES=VK_SUBGROUP_FEATURE_ARITHMETIC_BIT
  EXPECT "--raster binned needs subgroup arithmetic in compute shaders \\(VK_SUBGROUP_FEATURE_ARITHMETIC_BIT\\), which .* lacks: use --raster compute")

# The compute rasterisers in a real window (B8G8R8A8 there too; the golden
# image is the compute rasteriser's own, and the binned one must match the
# compute rasteriser's headless picture exactly there too).
if(XVFB_RUN)
  add_test(NAME chapter.20_ndim_compute.compute_raster.window
    COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24"
            $<TARGET_FILE:vkt_chapter_check> --exe $<TARGET_FILE:20_ndim_compute>
            --out ${VKT_TEST_OUTPUT} --name chapter.20_ndim_compute.compute_raster.window
            --golden ${VKT_GOLDEN_DIR}/20_ndim_compute_compute_raster.png
            --expect "20_ndim_compute: .*, window B8G8R8A8_" --
            --validation --frames ${VKT_TEST_FRAMES} --size ${VKT_TEST_SIZE} --raster compute)
  set_tests_properties(chapter.20_ndim_compute.compute_raster.window PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
  add_test(NAME chapter.20_ndim_compute.binned.window
    COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24"
            $<TARGET_FILE:vkt_chapter_check> --exe $<TARGET_FILE:20_ndim_compute>
            --out ${VKT_TEST_OUTPUT} --name chapter.20_ndim_compute.binned.window
            --same-as ${VKT_TEST_OUTPUT}/chapter.20_ndim_compute.compute_raster.headless.png
            --expect "20_ndim_compute: .*, window B8G8R8A8_" --
            --validation --frames ${VKT_TEST_FRAMES} --size ${VKT_TEST_SIZE} --raster binned)
  set_tests_properties(chapter.20_ndim_compute.binned.window PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
  vkt_same_picture(chapter.20_ndim_compute.binned.window chapter.20_ndim_compute.compute_raster.headless)
  # Drawn straight into the swapchain image, a frame has no storage view:
  # the copy, even with --to-target store. Through our own target
  # (--copy-to-swapchain), the resolve stores into it.
  foreach(variant "direct;copy" "copied;resolve")
    list(GET variant 0 how)
    list(GET variant 1 scope)
    set(test chapter.20_ndim_compute.store_binned.window_${how})
    set(copy)
    if(how STREQUAL "copied")
      set(copy --copy-to-swapchain)
    endif()
    add_test(NAME ${test}
      COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24"
              $<TARGET_FILE:vkt_chapter_check> --exe $<TARGET_FILE:20_ndim_compute>
              --out ${VKT_TEST_OUTPUT} --name ${test}
              --same-as ${VKT_TEST_OUTPUT}/chapter.20_ndim_compute.compute_raster.headless.png
              --expect "20_ndim_compute: .*, window B8G8R8A8_" --expect "\"${scope}\": \\{" --
              --validation --frames ${VKT_TEST_FRAMES} --size ${VKT_TEST_SIZE} --raster binned
              --to-target store --benchmark ${copy})
    set_tests_properties(${test} PROPERTIES
      ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
    vkt_same_picture(${test} chapter.20_ndim_compute.compute_raster.headless)
  endforeach()
endif()
