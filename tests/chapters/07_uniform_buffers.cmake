# Chapter 07: two cubes, their camera and transforms in uniform buffers.
#
# Hand-worked pixels (frame 9 of 10, t = 0.15 s): the corners are the clear
# colour (0.02, 0.02, 0.04), stored sRGB-encoded as (39, 39, 56). Each face has
# one flat colour, so a pixel well inside a face is exactly that colour,
# encoded: the big cube's +z face (0.1, 0.2, 0.8) faces right-front, at
# (190, 130), stored (89, 124, 231); its -x face (0.1, 0.6, 0.6), left-front,
# at (115, 130), stored (89, 203, 203); its top (0.1, 0.7, 0.1) at (160, 70),
# stored (89, 218, 89). The small cube, orbiting at the right, is tinted half
# way to white: its +z face (0.55, 0.6, 0.9) at (275, 134) is (196, 203, 243).
set(VKT_07_PIXEL PIXEL 0,0,39,39,56 319,239,39,39,56 190,130,89,124,231 115,130,89,203,203
                       160,70,89,218,89 275,134,196,203,243)
vkt_chapter_test(chapter.07_uniform_buffers 07_uniform_buffers GOLDEN BLESS ${VKT_07_PIXEL}
  ARGS ${headless})
vkt_chapter_test(chapter.07_uniform_buffers.offscreen 07_uniform_buffers SAME_AS chapter.07_uniform_buffers ${VKT_07_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(07_uniform_buffers PIXEL 190,130,89,124,231)

# A later frame, with the small cube behind the big one: without a depth
# buffer it is still drawn over it (the reason for chapter 08). At frame 119
# (t = 119/60 s) the orbit angle is 1.2 + 0.9 t = 2.985 rad: the small cube is
# at (0.34, 0, -2.17), straight behind the big cube, and at (170, 93), where
# the big cube's -x face (89, 203, 203) should be, its own -z face shows,
# tinted: (0.9, 0.85, 0.55), stored (243, 237, 196).
set(behind ${VKT_TEST_OUTPUT}/chapter.07_uniform_buffers.behind.png)
vkt_chapter_test(chapter.07_uniform_buffers.behind 07_uniform_buffers
  ARGS --headless --validation --frames 120 --size ${VKT_TEST_SIZE} --screenshot ${behind})
add_test(NAME chapter.07_uniform_buffers.behind_pixels
  COMMAND vkt_chapter_check --png ${behind} --pixel 170,93,243,237,196 --pixel 160,120,89,203,203)
set_tests_properties(chapter.07_uniform_buffers.behind PROPERTIES FIXTURES_SETUP ch07_behind)
set_tests_properties(chapter.07_uniform_buffers.behind_pixels PROPERTIES
  FIXTURES_REQUIRED ch07_behind LABELS chapter)

vkt_chapter_test(chapter.07_uniform_buffers.help 07_uniform_buffers EXIT 0 ARGS --help
  EXPECT "usage: 07_uniform_buffers" "--screenshot FILE")
vkt_chapter_test(bad_input.07_uniform_buffers.unknown_flag 07_uniform_buffers EXIT 2
  ARGS --objects 3 EXPECT "unknown argument '--objects'")
