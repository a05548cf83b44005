# Chapter 23: physically based materials and HDR.
vkt_chapter_test(chapter.23_materials 23_materials ARGS ${headless})
