# Chapter 13: a galaxy of particles moved by a compute shader, drawn as points.
#
# The picture is deterministic: the particles start from a hash of their
# index (no random numbers), and headless time is frame index / 60, so every
# frame runs exactly 2 fixed steps of 1/120 s; frame 9 (the screenshot) shows
# the galaxy after 18 steps.
vkt_chapter_test(chapter.13_compute 13_compute GOLDEN BLESS ARGS ${headless}
  EXPECT "13_compute: 65536 particles \\(2 MiB\\), workgroups of 256: 65536 invocations in 1 dispatch\\(es\\) of up to 4194304 particles, 0 idle; step 1/120 s")
vkt_chapter_test(chapter.13_compute.offscreen 13_compute GOLDEN ARGS ${offscreen})
vkt_chapter_window_test(13_compute)
# Splitting the work into 4 dispatches (each with its own window of the
# buffer) moves the same particles the same way: the same picture.
vkt_chapter_test(chapter.13_compute.split 13_compute GOLDEN ARGS ${headless} --dispatch-max 16384
  EXPECT "65536 invocations in 4 dispatch\\(es\\) of up to 16384 particles, 0 idle")
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
