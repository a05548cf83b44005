vkt_chapter_test(chapter.24_ray_queries 24_ray_queries GOLDEN BLESS ARGS ${headless})
