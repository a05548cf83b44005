# Chapter 12: a mirror-symmetric scene under coloured point lights, the left
# half lit per vertex and the right half per fragment.
#
# Hand-worked pixels, split (the default), frame 9 of 10: the top corners are
# background, the clear colour (0.02, 0.02, 0.04) stored sRGB-encoded as
# (39, 39, 56); the gap between the halves (columns 159 and 160 at 320 wide)
# shows it too.
#
# And the lesson: pixel (174, 88) lies on the squashed sphere (scaled 2.6,
# 0.9, 1.3), on the per-fragment half. Shaded on the CPU from the very
# triangles the chapter draws, its normals turned by the inverse transpose,
# with vkt::shade and the chapter's five lights at frame 9
# (tests/unit/test_lighting.cpp, "chapter 12's squashed sphere"): (207, 238,
# 182). With the model matrix for normals (--normal-matrix model) the same
# point is (83, 86, 84).
set(VKT_12_PIXEL PIXEL 0,0,39,39,56 319,0,39,39,56 160,120,39,39,56 159,200,39,39,56
                       174,88,207,238,182,2)
vkt_chapter_test(chapter.12_lighting 12_lighting GOLDEN BLESS ${VKT_12_PIXEL} ARGS ${headless}
  EXPECT "12_lighting: 5 lights, shading split, windowed falloff, normals by inverse-transpose")
vkt_chapter_test(chapter.12_lighting.offscreen 12_lighting SAME_AS chapter.12_lighting ${VKT_12_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(12_lighting PIXEL 160,120,39,39,56)

# The GPU against the CPU: one light, per fragment. The image centre shows the
# floor point (0, 0, 0) (the sample at the pixel's centre, (160.5, 120.5),
# lands at (0.019, 0, 0.043)); tests/unit/test_lighting.cpp works its colour
# out by hand and with vkt::shade: linear (0.4813, 0.4122, 0.3202) at the
# origin, (0.4763, 0.4080, 0.3169) at the sample, stored sRGB-encoded as
# (183, 171, 153).
vkt_chapter_test(chapter.12_lighting.one_light 12_lighting PIXEL 160,120,183,171,153,2
  ARGS ${headless} --lights 1 --shading fragment
  EXPECT "12_lighting: 1 light, shading fragment")
# The same with the classic falloff 1 / (1 + 0.35 d + 0.44 d^2): linear
# (0.6868, 0.5869, 0.4538) at the sample, stored (216, 201, 180).
vkt_chapter_test(chapter.12_lighting.one_light_classic 12_lighting PIXEL 160,120,216,201,180,2
  ARGS ${headless} --lights 1 --shading fragment --falloff classic)

# Per vertex, one light: the floor is 4 x 4 cells of 3 units, so the origin is
# a vertex, lit with exactly the colour worked out above, and the centre
# pixel's sample, 0.05 units from it in a 3-unit cell, interpolates 98% of
# it: the same (183, 171, 153) within 2.
vkt_chapter_test(chapter.12_lighting.one_light_vertex 12_lighting PIXEL 160,120,183,171,153,2
  ARGS ${headless} --lights 1 --shading vertex EXPECT "12_lighting: 1 light, shading vertex")

# The other modes run cleanly (no golden image: the book shows them), with
# the background where it belongs (per vertex all over there is no gap).
vkt_chapter_test(chapter.12_lighting.vertex 12_lighting PIXEL 0,0,39,39,56 319,0,39,39,56
  ARGS ${headless} --shading vertex EXPECT "shading vertex")
vkt_chapter_test(chapter.12_lighting.many_lights 12_lighting
  PIXEL 0,0,39,39,56 319,0,39,39,56 160,120,39,39,56 159,200,39,39,56
  ARGS ${offscreen} --lights 16 EXPECT "16 lights")
# The lesson itself: turning normals by the model matrix, not its inverse
# transpose, leans the normals of the non-uniformly scaled objects, and the
# picture must no longer pass as the chapter's golden image.
vkt_chapter_test(chapter.12_lighting.model_normals 12_lighting GOLDEN PIXEL 174,88,83,86,84,2
  ARGS ${headless} --normal-matrix model EXPECT "normals by model")
set_tests_properties(chapter.12_lighting.model_normals PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*12_lighting\\.png")
vkt_chapter_test(chapter.12_lighting.help 12_lighting EXIT 0 ARGS --help
  EXPECT "usage: 12_lighting" "--shading MODE" "--lights N" "--falloff KIND"
         "--normal-matrix KIND")

# Bad input: one clear line and exit status 2.
vkt_chapter_test(bad_input.12_lighting.no_lights 12_lighting EXIT 2 ARGS --lights 0
  EXPECT "--lights")
vkt_chapter_test(bad_input.12_lighting.too_many_lights 12_lighting EXIT 2 ARGS --lights 17
  EXPECT "--lights")
vkt_chapter_test(bad_input.12_lighting.lights_not_a_number 12_lighting EXIT 2 ARGS --lights many
  EXPECT "--lights")
vkt_chapter_test(bad_input.12_lighting.bad_shading 12_lighting EXIT 2 ARGS --shading flat
  EXPECT "--shading wants one of split, vertex, fragment, not 'flat'")
vkt_chapter_test(bad_input.12_lighting.bad_falloff 12_lighting EXIT 2 ARGS --falloff linear
  EXPECT "--falloff wants one of windowed, classic, not 'linear'")
