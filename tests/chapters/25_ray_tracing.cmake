# Chapter 25: the ray-tracing pipeline.
vkt_chapter_test(chapter.25_ray_tracing 25_ray_tracing GOLDEN BLESS ARGS ${headless}
  EXPECT "25_ray_tracing: 2 bounces, recursion depth 4 of [0-9]+")
vkt_chapter_test(chapter.25_ray_tracing.offscreen 25_ray_tracing GOLDEN ARGS ${offscreen})
