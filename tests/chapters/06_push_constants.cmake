# Chapter 06: twelve shapes, one pipeline, a transform and a colour per draw in
# push constants.
#
# Hand-worked pixels. The corners, and the image's centre (160,120), which
# falls between the second and third columns (each shape reaches at most
# 0.28 * 120 = 33.6 pixels from its centre at x = 120 and 200), are the clear
# colour, stored as (39, 39, 56). At an object's centre the shade is 1 (the
# white centre vertex) times the object's colour; the pixel's sample lies half
# a pixel off, where the shade is 0.985-0.987 instead. Object 0 (a triangle
# centred on pixel 40,40) has colour (1, 0.25, 0.25): 0.985 of it, sRGB
# encoded, is (253, 136, 136). Object 6 (a hexagon on 200,120), (0.25, 1, 1):
# (136, 254, 254). Neither depends on the rotation by more than a rounding.
set(VKT_06_PIXEL PIXEL 0,0,39,39,56 319,239,39,39,56 160,120,39,39,56
  40,40,253,136,136 200,120,136,254,254)
vkt_chapter_test(chapter.06_push_constants 06_push_constants GOLDEN BLESS ${VKT_06_PIXEL}
  ARGS ${headless})
vkt_chapter_test(chapter.06_push_constants.offscreen 06_push_constants SAME_AS chapter.06_push_constants ${VKT_06_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(06_push_constants PIXEL 40,40,253,136,136 200,120,136,254,254)

# No flags of its own: the shared ones, and --help lists them.
vkt_chapter_test(chapter.06_push_constants.help 06_push_constants EXIT 0 ARGS --help
  EXPECT "usage: 06_push_constants" "--screenshot FILE")
