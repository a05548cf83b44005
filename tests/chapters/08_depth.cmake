# Chapter 08: five intersecting boxes with a depth buffer and a perspective camera.
#
# Hand-worked pixels (frame 9 of 10): the corners are the clear colour,
# (39, 39, 56). Every face is one flat colour, so a pixel well inside a face
# is exactly that colour, sRGB-encoded:
# - (160, 120), the centre, on the big cube's +z face (0.1, 0.2, 0.8): (89, 124, 231);
# - (220, 90), inside the outline of the far cube, which is drawn last: the
#   depth test keeps the big cube's +z face, (89, 124, 231), in front of it;
# - (190, 140), where the bar (drawn after the big cube) runs inside the big
#   cube: the big cube's face again, (89, 124, 231);
# - (250, 60), the far cube's +z face tinted 40% towards (0.3, 0.3, 1):
#   (0.18, 0.24, 0.88), stored (118, 134, 241);
# - (60, 145), the bar's left end, its +z face darkened 35% towards black:
#   (0.065, 0.13, 0.52), stored (72, 101, 191).
set(VKT_08_PIXEL PIXEL 0,0,39,39,56 319,239,39,39,56 160,120,89,124,231 220,90,89,124,231
                       190,140,89,124,231 250,60,118,134,241 60,145,72,101,191)
vkt_chapter_test(chapter.08_depth 08_depth GOLDEN BLESS ${VKT_08_PIXEL} ARGS ${headless}
  EXPECT "08_depth: depth format: VK_FORMAT_D(32_SFLOAT|32_SFLOAT_S8_UINT|24_UNORM_S8_UINT|16_UNORM)")
vkt_chapter_test(chapter.08_depth.offscreen 08_depth SAME_AS chapter.08_depth ${VKT_08_PIXEL} ARGS ${offscreen})
vkt_chapter_window_test(08_depth PIXEL 160,120,89,124,231 220,90,89,124,231)

# lavapipe renders to D32_SFLOAT, the first choice: the format is reported.
vkt_chapter_test(chapter.08_depth.format 08_depth
  ARGS --offscreen --validation --frames 1 --size 64x48
  EXPECT "08_depth: depth format: VK_FORMAT_D32_SFLOAT")
# Many frames: one depth image shared by both frames in flight, with the
# barrier between frames, must keep synchronisation validation silent.
vkt_chapter_test(chapter.08_depth.many_frames 08_depth
  ARGS --headless --validation --frames 40 --size 96x72)

vkt_chapter_test(chapter.08_depth.help 08_depth EXIT 0 ARGS --help
  EXPECT "usage: 08_depth" "--screenshot FILE")
vkt_chapter_test(bad_input.08_depth.unknown_flag 08_depth EXIT 2 ARGS --depth 24
  EXPECT "unknown argument '--depth'")
