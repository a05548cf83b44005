# Chapter 24: chapter 22's scene and light, its shadows found by ray queries
# through an acceleration structure (--shadows rays, the default), by a
# shadow map (--shadows map), or both compared (--shadows compare).
#
# Hand-worked pixels: chapter 22's, for the same camera, light and floor (see
# tests/chapters/22_shadows.cmake): the sky corner (179, 203, 231); the lit
# floor point (2, 0, 4) at (272, 228), (214, 214, 208); the floor point
# (2.1, 0, 1.325) at (235, 166), whose ray to the light passes through the
# centre of the right front pillar, in shadow (111, 111, 108). The sphere and
# torus move, but neither comes near those two rays.
set(VKT_24_PIXEL PIXEL 0,0,179,203,231 272,228,214,214,208,2 235,166,111,111,108,2)
vkt_chapter_test(chapter.24_ray_queries 24_ray_queries GOLDEN BLESS ${VKT_24_PIXEL}
  ARGS ${headless}
  EXPECT "24_ray_queries: shadows rays, top level updated; 4 bottom levels .* KiB built, .* KiB compacted \\([0-9]+% saved\\)"
         "top level 19 instances")
vkt_chapter_test(chapter.24_ray_queries.offscreen 24_ray_queries SAME_AS chapter.24_ray_queries ${VKT_24_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(24_ray_queries PIXEL 0,0,179,203,231)
# Rebuilding the top level each frame instead of refitting it: the same
# picture, to the bit (both structures hold the same triangles), compared with
# the refitted run above, drawn by this build on this machine.
vkt_chapter_test(chapter.24_ray_queries.rebuild 24_ray_queries SAME_AS chapter.24_ray_queries
  ${VKT_24_PIXEL} ARGS ${headless} --tlas rebuild EXPECT "top level rebuilt")
# Later, the sphere has risen 0.29 and the torus turned 0.65 radians: the
# rebuilt structure's picture has its own golden (within the tolerance), and
# the refitted one must equal the rebuilt one's picture to the bit, so a top
# level left behind by the moving objects would show as shadows where they
# were.
vkt_chapter_test(chapter.24_ray_queries.moved_rebuild 24_ray_queries
  GOLDEN_FILE 24_ray_queries_frame40.png LABELS bless ${VKT_24_PIXEL}
  ARGS --headless --validation --frames 40 --size ${VKT_TEST_SIZE} --tlas rebuild)
vkt_chapter_test(chapter.24_ray_queries.moved_update 24_ray_queries
  SAME_AS chapter.24_ray_queries.moved_rebuild ${VKT_24_PIXEL}
  ARGS --headless --validation --frames 40 --size ${VKT_TEST_SIZE} --tlas update)
# And the comparison sees a shadow left where the objects were: the refitted
# top level at frame 39 against the rebuilt one at frame 9 (the objects
# have moved since) must fail, naming the picture.
vkt_chapter_test(chapter.24_ray_queries.moved_differs 24_ray_queries
  SAME_AS chapter.24_ray_queries.rebuild
  ARGS --headless --validation --frames 40 --size ${VKT_TEST_SIZE} --tlas update)
set_tests_properties(chapter.24_ray_queries.moved_differs PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*chapter\\.24_ray_queries\\.rebuild\\.png")
# The shadow map: the same hand-worked pixels, its own golden, and against the
# rays' picture the two methods agree on all but a few pixels: at most 2% of
# the pixels differ by more than 24 in a channel (lavapipe: 0.82%, the edges
# of shadows, where the map's texels and filtering blur what the rays find
# exactly), and the RMSE is at most 8 (lavapipe: 4.3).
vkt_chapter_test(chapter.24_ray_queries.map 24_ray_queries GOLDEN_FILE 24_ray_queries_map.png
  LABELS bless ${VKT_24_PIXEL} ARGS ${headless} --shadows map EXPECT "shadows map")
vkt_chapter_test(chapter.24_ray_queries.map_agrees 24_ray_queries GOLDEN TOLERANCE 8,24,0.02
  ${VKT_24_PIXEL} ARGS ${headless} --shadows map)
# And the two do differ: under the ordinary tolerance of a golden test
# (0.2% of the pixels), the map's picture fails against the rays' golden, so
# the comparison above can fail, and does not bless (LABELS chapter only).
add_test(NAME chapter.24_ray_queries.map_differs
  COMMAND vkt_chapter_check --exe $<TARGET_FILE:24_ray_queries> --out ${VKT_TEST_OUTPUT}
          --name chapter.24_ray_queries.map_differs --golden ${VKT_GOLDEN_DIR}/24_ray_queries.png
          --tolerance 2,24,0.002 -- ${headless} --shadows map)
set_tests_properties(chapter.24_ray_queries.map_differs PROPERTIES
  ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS chapter
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*24_ray_queries\\.png")
# The comparison the page shows: grey where the two agree, red where only the
# map shadows, blue where only the rays do. The sky is the clear colour.
vkt_chapter_test(chapter.24_ray_queries.compare 24_ray_queries
  GOLDEN_FILE 24_ray_queries_compare.png LABELS bless PIXEL 0,0,179,203,231
  ARGS ${headless} --shadows compare EXPECT "shadows compare")
# Many moving instances (the benchmark's --crowd): far behind the pillars,
# they leave the hand-worked pixels as they were.
vkt_chapter_test(chapter.24_ray_queries.crowd 24_ray_queries ${VKT_24_PIXEL}
  ARGS --headless --validation --frames 3 --size ${VKT_TEST_SIZE} --crowd 256
  EXPECT "top level 275 instances")
vkt_chapter_test(chapter.24_ray_queries.help 24_ray_queries EXIT 0 ARGS --help
  EXPECT "usage: 24_ray_queries" "--shadows HOW" "--tlas HOW" "--crowd N" "--ray-offset D\\|ulp")
# Where the shadow ray starts (--ray-offset, page 24b's "Where the ray
# starts"): scene.frag's specialization constants. Given as its default,
# 0.01 along the normal, it draws the default's picture to the bit.
vkt_chapter_test(chapter.24_ray_queries.ray_offset_default 24_ray_queries
  SAME_AS chapter.24_ray_queries ${VKT_24_PIXEL} ARGS ${headless} --ray-offset 0.01)
# Started on the surface (0), rays hit the triangles they leave: acne over
# the lit surfaces (lavapipe: 9.8% of the pixels differ from the default's
# golden by more than 24 in a channel), so the picture must fail against the
# golden even with 5% of the pixels allowed to differ.
vkt_chapter_test(chapter.24_ray_queries.ray_offset_zero 24_ray_queries
  GOLDEN TOLERANCE 8,24,0.05 ARGS ${headless} --ray-offset 0)
set_tests_properties(chapter.24_ray_queries.ray_offset_zero PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*24_ray_queries\\.png")
# Waechter and Binder's floating-point offset alone (ulp) leaves blue specks
# on the sphere and the torus in the comparison, 84 pixels changed at
# 320x240 on lavapipe (the page counts them), so the picture fails against
# the comparison's golden with 0.05% (38 pixels) allowed to differ.
vkt_chapter_test(chapter.24_ray_queries.ray_offset_ulp 24_ray_queries
  GOLDEN_FILE 24_ray_queries_compare.png TOLERANCE 8,24,0.0005
  ARGS ${headless} --shadows compare --ray-offset ulp)
set_tests_properties(chapter.24_ray_queries.ray_offset_ulp PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*24_ray_queries_compare\\.png")

# A device without ray queries (the H100's driver offers acceleration
# structures and ray-tracing pipelines but not VK_KHR_ray_query), or without
# what the structures need: one line naming what it lacks, exit status 1.
foreach(missing VK_KHR_ray_query VK_KHR_acceleration_structure VK_KHR_deferred_host_operations)
  vkt_chapter_test(bad_input.24_ray_queries.no_${missing} 24_ray_queries EXIT 1
    ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=${missing}
    EXPECT "no Vulkan device can run this chapter; .* lacks the extension ${missing} \\(hidden by VKT_HIDE_FEATURES\\)")
endforeach()
foreach(missing rayQuery:VK_KHR_ray_query accelerationStructure:VK_KHR_acceleration_structure)
  string(REPLACE ":" ";" pair ${missing})
  list(GET pair 0 feature)
  list(GET pair 1 extension)
  vkt_chapter_test(bad_input.24_ray_queries.no_${feature} 24_ray_queries EXIT 1
    ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=${feature}
    EXPECT "no Vulkan device can run this chapter; .* lacks the ${feature} feature of ${extension} \\(hidden by VKT_HIDE_FEATURES\\)")
endforeach()
vkt_chapter_test(bad_input.24_ray_queries.no_bufferDeviceAddress 24_ray_queries EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=bufferDeviceAddress
  EXPECT "no Vulkan device can run this chapter; .* lacks the bufferDeviceAddress feature")
# Bad input: one clear line and exit status 2.
vkt_chapter_test(bad_input.24_ray_queries.bad_shadows 24_ray_queries EXIT 2 ARGS --shadows maps
  EXPECT "--shadows wants one of map, rays, compare, not 'maps'")
vkt_chapter_test(bad_input.24_ray_queries.bad_tlas 24_ray_queries EXIT 2 ARGS --tlas refit
  EXPECT "--tlas wants one of update, rebuild, not 'refit'")
vkt_chapter_test(bad_input.24_ray_queries.bad_crowd 24_ray_queries EXIT 2 ARGS --crowd 16385
  EXPECT "--crowd wants a whole number from 0 to 16384, not '16385'")
vkt_chapter_test(bad_input.24_ray_queries.crowd_word 24_ray_queries EXIT 2 ARGS --crowd many
  EXPECT "--crowd wants a whole number")
vkt_chapter_test(bad_input.24_ray_queries.bad_ray_offset 24_ray_queries EXIT 2 ARGS --ray-offset 2
  EXPECT "--ray-offset wants a distance from 0 to 1 along the normal, or ulp, not '2'")
vkt_chapter_test(bad_input.24_ray_queries.ray_offset_word 24_ray_queries EXIT 2
  ARGS --ray-offset far EXPECT "--ray-offset wants a distance from 0 to 1 .*, not 'far'")
# The boxes view: the lit scene and, over it, each bottom level's box carried
# into the world (orange) and each instance's axis-aligned box in the top
# level (blue, drawn second). Hand-worked: the sphere (radius 0.5, scaled
# 1.4, centre (-0.8, 0.7 + 0.3 sin 2t, 3), t = 9 / 60 at the tenth frame) is
# not turned, so both its boxes are the cube of half-side 0.7 round it; the
# back top edge, y = 1.489 and z = 2.3, projects to row 123.66 at 320x240,
# across columns 94.5 to 155.6. So (110, 123) is blue (0.15, 0.3, 1), stored
# (108, 149, 255), and (110, 125) just below it is lit floor.
vkt_chapter_test(chapter.24_ray_queries.boxes 24_ray_queries GOLDEN_FILE 24_ray_queries_boxes.png
  LABELS bless PIXEL 110,123,108,149,255 110,125,214,214,208,2
  ARGS ${headless} --view boxes EXPECT "boxes drawn: orange, each bottom level's bounds")
vkt_chapter_test(bad_input.24_ray_queries.bad_view 24_ray_queries EXIT 2 ARGS --view tree
  EXPECT "--view wants one of scene, boxes, not 'tree'")

# The acceleration-structure benchmark (as_bench, benchmarks/acceleration_build.cpp),
# briefly, with validation on, so that it cannot rot: chapter 24's bottom
# levels and a small dense sphere built, their compacted sizes queried and
# copied, and the top level rebuilt and refitted at two instance counts.
vkt_chapter_test(chapter.24_ray_queries.as_bench as_bench
  ARGS --validation --rounds 2 --builds 3 --instances 19,300 --dense 64,364
  EXPECT "as_bench: .*validation on, 2 rounds, 3 top-level builds per round"
         "chapter 24's build_bottom_levels: 4 bottom levels .* KiB built, .* KiB compacted"
         "blas torus 48x16 +1536 triangles: build [0-9.]+ ms"
         "blas sphere 64x32 \\(16-bit\\) +3968 triangles"
         "blas sphere 364x182 \\(32-bit\\) +131768 triangles: build [0-9.]+ ms .* compacting copy [0-9.]+ ms"
         "tlas +19 instances: rebuild [0-9.]+ ms .* update [0-9.]+ ms"
         "tlas +300 instances: rebuild")
# It needs VK_KHR_acceleration_structure (not ray queries): without it, one
# line naming it and exit status 1; a bad list, exit status 2.
vkt_chapter_test(bad_input.24_ray_queries.as_bench_no_acceleration as_bench EXIT 1
  ARGS --rounds 1 ENV VKT_HIDE_FEATURES=VK_KHR_acceleration_structure
  EXPECT "as_bench: no Vulkan device can run this chapter; .* lacks the extension VK_KHR_acceleration_structure")
vkt_chapter_test(bad_input.24_ray_queries.as_bench_bad_instances as_bench EXIT 2
  ARGS --instances 19,,100
  EXPECT "--instances wants whole numbers from 1 to 1000000 separated by commas, not '19,,100'")
# The build-size query needs a ray feature enabled (the ray-tracing pipeline's
# or ray queries'): a device with neither is named, exit status 1.
vkt_chapter_test(bad_input.24_ray_queries.as_bench_no_tracer as_bench EXIT 1
  ARGS --rounds 1 ENV VKT_HIDE_FEATURES=VK_KHR_ray_tracing_pipeline,VK_KHR_ray_query
  EXPECT "as_bench: llvmpipe.* lacks both VK_KHR_ray_tracing_pipeline and VK_KHR_ray_query")
