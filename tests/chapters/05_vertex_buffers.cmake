# Chapter 05: a hexagon from a vertex buffer and an index buffer.
#
# Hand-worked pixels: the corners are the clear colour (0.02, 0.02, 0.04),
# stored sRGB-encoded as (39, 39, 56). The centre pixel samples clip space
# (0.0031, 0.0042), a hair from the centre vertex: 99.1% of its light grey
# 0.8 and a trace of two rim colours, linear (0.793, 0.802, 0.795). The _SRGB
# target stores 0.8 as 231 (a raw UNORM store would give 204); the trace moves
# it by at most 1, so within 2 of (231, 231, 231).
set(VKT_05_PIXEL PIXEL 0,0,39,39,56 319,239,39,39,56 160,120,231,231,231,2)
vkt_chapter_test(chapter.05_vertex_buffers 05_vertex_buffers GOLDEN BLESS ${VKT_05_PIXEL}
  ARGS ${headless} EXPECT "05_vertex_buffers: memory type 0: heap 0")
vkt_chapter_test(chapter.05_vertex_buffers.offscreen 05_vertex_buffers SAME_AS chapter.05_vertex_buffers ${VKT_05_PIXEL}
  ARGS ${offscreen})
vkt_chapter_window_test(05_vertex_buffers PIXEL 160,120,231,231,231,2)

# No flags of its own: the shared ones, and --help lists them.
vkt_chapter_test(chapter.05_vertex_buffers.help 05_vertex_buffers EXIT 0 ARGS --help
  EXPECT "usage: 05_vertex_buffers" "--screenshot FILE")
vkt_chapter_test(bad_input.05_vertex_buffers.unknown_flag 05_vertex_buffers EXIT 2 ARGS --indices 3
  EXPECT "unknown argument '--indices'")
