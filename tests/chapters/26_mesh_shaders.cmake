# Chapter 26: task and mesh shaders drawing the knot in meshlets.
vkt_chapter_test(chapter.26_mesh_shaders 26_mesh_shaders GOLDEN BLESS ARGS ${headless})
