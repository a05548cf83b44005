# Chapter 13: a galaxy of particles moved by a compute shader, drawn as points.
#
# The picture is deterministic: the particles start from a hash of their
# index (no random numbers), and headless time is frame index / 60, so every
# frame runs exactly 2 fixed steps of 1/120 s; frame 9 (the screenshot) shows
# the galaxy after 18 steps.
# The background: the clear colour (0.002, 0.002, 0.008), stored by the _SRGB
# target as (7, 7, 22).
set(VKT_13_PIXEL PIXEL 0,0,7,7,22 319,239,7,7,22)
vkt_chapter_test(chapter.13_compute 13_compute GOLDEN BLESS ${VKT_13_PIXEL} ARGS ${headless}
  EXPECT "13_compute: 65536 particles \\(2 MiB\\), workgroups of 256: 65536 invocations in 1 dispatch\\(es\\) of up to 4194304 particles, 0 idle; step 1/120 s")
vkt_chapter_test(chapter.13_compute.offscreen 13_compute SAME_AS chapter.13_compute ${VKT_13_PIXEL} ARGS ${offscreen})
vkt_chapter_window_test(13_compute)
# Splitting the work into 4 dispatches (each with its own window of the
# buffer) moves the same particles the same way: the same picture.
vkt_chapter_test(chapter.13_compute.split 13_compute SAME_AS chapter.13_compute ARGS ${headless} --dispatch-max 16384
  EXPECT "65536 invocations in 4 dispatch\\(es\\) of up to 16384 particles, 0 idle")
# One particle, worked out by hand (the page's "One particle by hand"):
# particle 0's hash is 0, so it starts at radius 0.08 on arm 0, at
# (0.0788, 0.0253, 0.0137); 18 steps of semi-implicit Euler take it to
# (-0.0653, -0.0177, 0.0489), which the camera projects to (155.51, 101.46):
# pixel (155, 101). Its colour (1.0, 0.85, 0.6) at alpha 0.5 over the
# background is linear (0.501, 0.426, 0.304), stored (188, 174.5, 150): 174
# or 175, so within 2. Its neighbours, and where it started, (165, 97), are
# background: a point of size 1 covers one pixel.
set(one_particle ${VKT_TEST_OUTPUT}/chapter.13_compute.one_particle.png)
vkt_chapter_test(chapter.13_compute.one_particle 13_compute
  ARGS ${headless} --count 1 --screenshot ${one_particle})
add_test(NAME chapter.13_compute.one_particle_pixels
  COMMAND vkt_chapter_check --png ${one_particle} --pixel 155,101,188,175,150,2
          --pixel 154,101,7,7,22 --pixel 156,101,7,7,22 --pixel 155,100,7,7,22
          --pixel 155,102,7,7,22 --pixel 165,97,7,7,22)
set_tests_properties(chapter.13_compute.one_particle PROPERTIES FIXTURES_SETUP ch13_one_particle)
set_tests_properties(chapter.13_compute.one_particle_pixels PROPERTIES
  FIXTURES_REQUIRED ch13_one_particle LABELS chapter)

# A count that is not a multiple of the workgroup: 4 groups, 24 idle
# invocations that the bounds check keeps off the buffer (validation and the
# robust exit would catch a write past the end); then the same in two chunks,
# the last one ragged.
vkt_chapter_test(chapter.13_compute.partial_group 13_compute ARGS ${headless} --count 1000
  EXPECT "1000 particles .* 1024 invocations in 1 dispatch\\(es\\) .* 24 idle")
vkt_chapter_test(chapter.13_compute.partial_chunks 13_compute ARGS ${headless} --count 1000
  --dispatch-max 512 EXPECT "1000 particles .* 1024 invocations in 2 dispatch\\(es\\) of up to 512 particles, 24 idle")
# One particle more than lavapipe's 4,194,304 per dispatch (its
# maxStorageBufferRange of 128 MiB over 32 bytes): a second dispatch of one
# workgroup with 255 idle invocations. (16,777,216 particles work as well,
# in 4 dispatches, but drawing them takes lavapipe about 30 s a frame: see
# benchmarks/13_compute.md.)
vkt_chapter_test(chapter.13_compute.limit_split 13_compute
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE} --count 4194305
  EXPECT "4194305 particles \\(129 MiB\\), workgroups of 256: 4194560 invocations in 2 dispatch\\(es\\) of up to 4194304 particles, 255 idle")
# --benchmark reports the two GPU scopes the chapter names.
vkt_chapter_test(chapter.13_compute.benchmark 13_compute
  ARGS --headless --no-validation --frames 10 --size ${VKT_TEST_SIZE} --benchmark
  EXPECT "\"gpu_scopes_ms\": \\{\"simulate\": \\{\"min\": [0-9.]+, \"median\": [0-9.]+, \"p95\": [0-9.]+, \"max\": [0-9.]+\\}, \"draw\": \\{\"min\": [0-9.]+")
vkt_chapter_test(chapter.13_compute.help 13_compute EXIT 0 ARGS --help
  EXPECT "usage: 13_compute" "--count N" "--dispatch-max N")

# Bad input. The command line: no particles, more than the option allows, a
# dispatch smaller than one workgroup (status 2).
vkt_chapter_test(bad_input.13_compute.count_zero 13_compute EXIT 2 ARGS --count 0
  EXPECT "--count wants a whole number from 1 to 268435456, not '0'")
vkt_chapter_test(bad_input.13_compute.count_too_many 13_compute EXIT 2 ARGS --count 268435457
  EXPECT "--count wants a whole number from 1 to 268435456, not '268435457'")
vkt_chapter_test(bad_input.13_compute.dispatch_max_small 13_compute EXIT 2 ARGS --dispatch-max 100
  EXPECT "--dispatch-max wants a whole number from 256 to 268435456, not '100'")
# The device: counts the option allows but lavapipe cannot hold in one buffer
# (status 1, naming the limit): 3.2 GB is more than one allocation may be
# (maxMemoryAllocationSize, 2 GiB), 6.4 GB more than one buffer (maxBufferSize,
# 4 GiB - 1).
vkt_chapter_test(bad_input.13_compute.count_beyond_allocation 13_compute EXIT 1
  ARGS --headless --frames 1 --count 100000000
  EXPECT "13_compute: error: --count 100000000 needs 3052 MiB of particles \\(32 bytes each\\) in one buffer, more than this device's maxMemoryAllocationSize of 2048 MiB")
vkt_chapter_test(bad_input.13_compute.count_beyond_buffer 13_compute EXIT 1
  ARGS --headless --frames 1 --count 200000000
  EXPECT "--count 200000000 needs 6104 MiB of particles \\(32 bytes each\\) in one buffer, more than this device's maxBufferSize of 4095 MiB")
# The workgroup size as a specialization constant needs maintenance4 (see
# the spec in main.cpp): a device without it is refused with the feature's name.
vkt_chapter_test(bad_input.13_compute.missing_feature 13_compute EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=maintenance4
  EXPECT "no Vulkan device can run this chapter; .* lacks the maintenance4 feature")
