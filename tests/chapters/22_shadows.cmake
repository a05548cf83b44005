# Chapter 22: a long floor with two rows of pillars, a sphere and a torus
# under one directional light. The chapter's default is one shadow map (the
# core page, book/22_shadows.md); the tests that draw 22b's three cascades ask
# for them with --cascades 3 (VKT_22_ARGS), so that each golden keeps the
# picture it was blessed with.
#
# Hand-worked pixels (tests/unit/test_cascades.cpp has the geometry): the
# top-left corner is sky, the clear colour (0.45, 0.6, 0.8) stored
# sRGB-encoded as (179, 203, 231). The light travels along (-0.6, -1, -0.45)
# / 1.25, so the floor's Lambert term is 1 / 1.25 = 0.8.
#  - Lit: the floor point (2, 0, 4), at pixel (272, 228) at 320x240: nothing
#    lies between it and the light; floor colour (0.8, 0.8, 0.75) times
#    0.2 + 0.8 * 0.8 = 0.84, stored (214, 214, 208).
#  - In shadow: the floor point (2.1, 0, 1.325), at pixel (235, 166): the ray
#    from it to the light passes through the centre of the right front pillar
#    (3, 1.5, 2); floor colour times the ambient 0.2 alone, stored (111, 111, 108).
set(VKT_22_PIXEL PIXEL 0,0,179,203,231 272,228,214,214,208,2 235,166,111,111,108,2)
set(VKT_22_ARGS --cascades 3)
vkt_chapter_test(chapter.22_shadows 22_shadows GOLDEN BLESS ${VKT_22_PIXEL} ARGS ${headless} ${VKT_22_ARGS}
  EXPECT "22_shadows: 3 cascades of 1024x1024, splits at 8.5 20.3 60.0 60.0, bias 4.00 \\+ 4.00 x slope")
vkt_chapter_test(chapter.22_shadows.offscreen 22_shadows SAME_AS chapter.22_shadows ${VKT_22_PIXEL}
  ARGS ${offscreen} ${VKT_22_ARGS})
vkt_chapter_window_test(22_shadows PIXEL 0,0,179,203,231 ARGS ${VKT_22_ARGS})
# The cascade view: each cascade tinted; its own golden (LABELS bless).
vkt_chapter_test(chapter.22_shadows.cascades 22_shadows GOLDEN_FILE 22_shadows_cascades.png
  LABELS bless PIXEL 0,0,179,203,231 ARGS ${headless} ${VKT_22_ARGS} --view cascades
  EXPECT "cascades coloured")
# The map view: each cascade's layer of the shadow map as a square, side by
# side, depth stretched from the slice's nearest to 1 over black to white.
# At 320x240 with three cascades a square is 106 pixels (320 / 3 the limit),
# its corner at (1, 67). Hand-worked: (0, 0) is the background (0.1, 0.1,
# 0.12), stored sRGB-encoded (89, 89, 97); (1, 100) is cascade 0's frame
# (1, 0.3, 0.3), (255, 149, 149); (5, 70), cascade 0's far corner from the
# camera, is a texel no caster covers (the light's box reaches past the
# floor there): it keeps the clear depth 1.0, drawn pale blue (0.6, 0.75, 1),
# (203, 225, 255). The grey between is the golden's.
vkt_chapter_test(chapter.22_shadows.map 22_shadows GOLDEN_FILE 22_shadows_map.png
  LABELS bless PIXEL 0,0,89,89,97 1,100,255,149,149 5,70,203,225,255
  ARGS ${headless} ${VKT_22_ARGS} --view map EXPECT "the shadow map shown")
# One cascade and four: the same shadow and the same light at the two pixels.
# One cascade is the one map of the core page (book/22_shadows.md), which
# shows this picture, so it has its own golden (LABELS bless). It is the
# chapter's default: this test passes no --cascades, so it fails if the
# default drifts from the core page's one map.
vkt_chapter_test(chapter.22_shadows.one_cascade 22_shadows
  GOLDEN_FILE 22_shadows_one_cascade.png LABELS bless ${VKT_22_PIXEL}
  ARGS ${headless} EXPECT "22_shadows: 1 cascade of 1024x1024")
# The core page's acne and peter-panning, with its one map. Without bias the
# lit pixel falls strictly between lit (214) and full shadow (111), as with
# three cascades (lavapipe: 188). The one map's texels are seven times as wide
# as the near cascade's, so the slope term moves depths seven times as far:
# a slope factor of 20 already lifts the right front pillar's shadow off the
# floor point at (235, 166), which is lit.
vkt_chapter_test(chapter.22_shadows.one_cascade.no_bias 22_shadows
  GOLDEN_FILE 22_shadows_one_cascade_acne.png LABELS bless PIXEL 272,228,163,163,158,33
  ARGS ${headless} --cascades 1 --bias-constant 0 --bias-slope 0
  EXPECT "1 cascade of 1024x1024.*bias 0.00 \\+ 0.00 x slope")
vkt_chapter_test(chapter.22_shadows.one_cascade.peter_panning 22_shadows
  GOLDEN_FILE 22_shadows_one_cascade_peter_panning.png LABELS bless PIXEL 235,166,214,214,208,2
  ARGS ${headless} --cascades 1 --bias-slope 20
  EXPECT "1 cascade of 1024x1024.*bias 4.00 \\+ 20.00 x slope")
vkt_chapter_test(chapter.22_shadows.four_cascades 22_shadows ${VKT_22_PIXEL}
  ARGS ${headless} --cascades 4 EXPECT "4 cascades of 1024x1024")
# Without the bias the lit floor shadows itself (acne): around the lit pixel
# the floor becomes bands of part-shadow (lavapipe: 156 and 188 where 214 was
# lit). The pixel must lie strictly between lit (214) and full shadow (111):
# 163 +- 33 takes 130..196, neither.
vkt_chapter_test(chapter.22_shadows.no_bias 22_shadows GOLDEN_FILE 22_shadows_acne.png
  LABELS bless PIXEL 272,228,163,163,158,33
  ARGS ${headless} ${VKT_22_ARGS} --bias-constant 0 --bias-slope 0
  EXPECT "3 cascades of 1024x1024.*bias 0.00 \\+ 0.00 x slope")
# Far too much slope bias pushes the casters' depths so far from the light
# that the shadows come loose from them (peter-panning): the floor point the
# pillar shades, at (235, 166), is lit (214, 214, 208).
vkt_chapter_test(chapter.22_shadows.peter_panning 22_shadows
  GOLDEN_FILE 22_shadows_peter_panning.png LABELS bless PIXEL 235,166,214,214,208,2
  ARGS ${headless} ${VKT_22_ARGS} --bias-slope 150
  EXPECT "3 cascades of 1024x1024.*bias 4.00 \\+ 150.00 x slope")
vkt_chapter_test(chapter.22_shadows.help 22_shadows EXIT 0 ARGS --help
  EXPECT "usage: 22_shadows" "--cascades N" "--view VIEW" "--bias-constant F" "--bias-slope F"
         "how many cascades split the view .*\\[default: 1\\]")

# Bad input: one clear line and exit status 2.
vkt_chapter_test(bad_input.22_shadows.no_cascades 22_shadows EXIT 2 ARGS --cascades 0
  EXPECT "--cascades")
vkt_chapter_test(bad_input.22_shadows.five_cascades 22_shadows EXIT 2 ARGS --cascades 5
  EXPECT "--cascades")
vkt_chapter_test(bad_input.22_shadows.bad_view 22_shadows EXIT 2 ARGS --view depth
  EXPECT "--view wants one of lit, cascades, map, not 'depth'")
vkt_chapter_test(bad_input.22_shadows.bad_bias_constant 22_shadows EXIT 2
  ARGS --bias-constant -1 EXPECT "--bias-constant wants a number from 0 to 1000")
vkt_chapter_test(bad_input.22_shadows.bad_bias_slope 22_shadows EXIT 2
  ARGS --bias-slope steep EXPECT "--bias-slope wants a number")
vkt_chapter_test(bad_input.22_shadows.too_much_slope 22_shadows EXIT 2
  ARGS --bias-slope 201 EXPECT "--bias-slope wants a number from 0 to 200, not '201'")
