# Chapter 16: deferred shading. The scene under 32 moving lights, drawn through
# a G-buffer (base colour, normal, material, depth) and a lighting pass.
#
# Hand-worked pixels: the top corners show no geometry, so the lighting pass
# writes the background (0.02, 0.02, 0.04), stored sRGB-encoded as (39, 39, 56),
# the same colour the forward path clears to. And two pixels of bare floor
# lit by the moving lights at frame 9, worked out on the CPU from the camera,
# the floor's material and make_lights (tests/unit/test_deferred.cpp,
# "chapters 16 and 17: lit floor pixels"): a pink pool at (234, 165),
# (242, 94, 188), and a cyan one at (159, 156), (125, 194, 193).
set(VKT_16_PIXEL PIXEL 0,0,39,39,56 319,0,39,39,56 234,165,242,94,188,2 159,156,125,194,193,2)
vkt_chapter_test(chapter.16_deferred 16_deferred GOLDEN BLESS ${VKT_16_PIXEL} ARGS ${headless}
  EXPECT "16_deferred: 32 lights, path deferred, view lit")
vkt_chapter_test(chapter.16_deferred.offscreen 16_deferred SAME_AS chapter.16_deferred ${VKT_16_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(16_deferred PIXEL 0,0,39,39,56)

# The forward path against the deferred golden image, with the golden tests'
# tolerance (vkt::Tolerance: RMSE at most 2, at most 0.2% of pixels off by
# more than 24). The tighter per-pixel check is chapter.16_deferred.verify_forward.
vkt_chapter_test(chapter.16_deferred.forward 16_deferred GOLDEN ${VKT_16_PIXEL}
  ARGS ${headless} --path forward EXPECT "path forward")

# One golden image per debug view: each G-buffer target alone. The checker is
# called directly, to name each view's own golden image. Hand-worked pixels:
# where nothing is drawn (the corner) every view shows black (the G-buffer's
# clear values; the depth view's far end). The bottom middle pixel is floor:
# albedo 0.7, stored sRGB-encoded as 218; normal (0, 1, 0), shown as
# n / 2 + 1/2 = (128, 255, 128); material specular 26/255 and shininess
# 16/255, shown as (26, 16, 0); that floor point, seen through the pixel's
# centre (160.5, 239.5), lies at (0.012, 0, 5.329), 7.604 from the eye at
# (0, 6, 10): the depth view shows 1 - 7.604 / 20 = 0.620 as 158.
set(VKT_16_VIEW_PIXELS_albedo 160,239,218,218,218)
set(VKT_16_VIEW_PIXELS_normal 160,239,128,255,128)
set(VKT_16_VIEW_PIXELS_material 160,239,26,16,0)
set(VKT_16_VIEW_PIXELS_depth 160,239,158,158,158)
foreach(view albedo normal material depth)
  set(test chapter.16_deferred.view_${view})
  set(pixels --pixel 0,0,0,0,0)
  foreach(pixel IN LISTS VKT_16_VIEW_PIXELS_${view})
    list(APPEND pixels --pixel ${pixel})
  endforeach()
  add_test(NAME ${test} COMMAND vkt_chapter_check --exe $<TARGET_FILE:16_deferred>
    --out ${VKT_TEST_OUTPUT} --name ${test} --golden ${VKT_GOLDEN_DIR}/16_deferred_${view}.png --blesses
    ${pixels} --expect "view ${view}" -- ${headless} --view ${view})
  set_tests_properties(${test} PROPERTIES ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}"
    LABELS "chapter;bless")
endforeach()

# --verify: the last frame again, into float targets, read back and checked
# (common/scene/include/vkt/scene/deferred_verify.hpp):
#   cpu         the lighting pass against vkt::shade_gbuffer on the read-back
#               G-buffer: largest difference at most 2e-3 (relative above 1;
#               lavapipe 6e-6, an H100 9e-4: GPUs may approximate pow)
#   additivity  lights A + lights B against A and B in one pass: at most 1e-5;
#               the lights lifted out of reach add exactly 0
#   forward     forward against deferred: at most 1.5 sRGB levels of 255 on
#               every pixel
vkt_chapter_test(chapter.16_deferred.verify_cpu 16_deferred ARGS ${headless} --verify cpu
  EXPECT "verify cpu: GPU lighting pass vs CPU reference")
vkt_chapter_test(chapter.16_deferred.verify_cpu_many 16_deferred
  ARGS ${offscreen} --verify cpu --lights 300 EXPECT "300 lights")
vkt_chapter_test(chapter.16_deferred.verify_additivity 16_deferred
  ARGS ${headless} --verify additivity
  EXPECT "lights out of reach add at most 0 " "verify additivity: lights A \\+ lights B")
vkt_chapter_test(chapter.16_deferred.verify_forward 16_deferred ARGS ${headless} --verify forward
  EXPECT "verify forward: forward vs deferred")

# --benchmark times the passes as named GPU scopes.
vkt_chapter_test(chapter.16_deferred.benchmark 16_deferred
  ARGS --offscreen --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark
  EXPECT "\"gpu_scopes_ms\": \\{\"gbuffer\": \\{\"min\": [0-9.]+.*\"lighting\": \\{")
vkt_chapter_test(chapter.16_deferred.benchmark_forward 16_deferred
  ARGS --offscreen --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark --path forward
  EXPECT "\"gpu_scopes_ms\": \\{\"forward\": \\{\"min\": [0-9.]+")
vkt_chapter_test(chapter.16_deferred.most_lights 16_deferred
  ARGS --offscreen --validation --frames 2 --size 64x48 --lights 65536 EXPECT "65536 lights")
vkt_chapter_test(chapter.16_deferred.help 16_deferred EXIT 0 ARGS --help
  EXPECT "usage: 16_deferred" "--path PATH" "--view VIEW" "--lights N" "--verify CHECK")

# Bad input: one clear line and a non-zero exit status.
# The most is our own limit of 65,536 (2 MiB of lights per frame in flight).
vkt_chapter_test(bad_input.16_deferred.no_lights 16_deferred EXIT 2 ARGS --lights 0
  EXPECT "--lights wants a whole number from 1 to 65536, not '0'")
vkt_chapter_test(bad_input.16_deferred.too_many_lights 16_deferred EXIT 2 ARGS --lights 65537
  EXPECT "--lights wants a whole number from 1 to 65536, not '65537'")
vkt_chapter_test(bad_input.16_deferred.bad_view 16_deferred EXIT 2 ARGS --view specular
  EXPECT "--view wants one of lit, albedo, normal, material, depth, not 'specular'")
vkt_chapter_test(bad_input.16_deferred.bad_path 16_deferred EXIT 2 ARGS --path tiled
  EXPECT "--path wants one of deferred, forward, not 'tiled'")

# Flags that contradict each other are bad input too: found before any device
# is made (the usage line shows it), exit status 2.
vkt_chapter_test(bad_input.16_deferred.view_needs_deferred 16_deferred EXIT 2
  ARGS --headless --frames 1 --path forward --view albedo
  EXPECT "--view albedo shows a G-buffer target: it needs --path deferred" "usage: 16_deferred")
vkt_chapter_test(bad_input.16_deferred.verify_forward_path 16_deferred EXIT 2
  ARGS --headless --frames 1 --path forward --verify cpu
  EXPECT "--verify renders both paths itself" "usage: 16_deferred")
