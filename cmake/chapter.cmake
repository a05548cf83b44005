# vkt_add_chapter(<NN_name> [OVERLAY] [SHADERS files...] [SHARED_SHADERS files...])
# One executable per chapter, linked to the helper library. SHADERS live in
# shaders/<NN_name>/; SHARED_SHADERS (paths under shaders/common/) are what an
# earlier chapter taught and a later one reuses. Both compile into the
# chapter's own SPIR-V folder, so no chapter loads another chapter's files.
# OVERLAY: the chapter has the on-screen overlay (ChapterSpec::overlay,
# chapter 21), whose shaders it then carries too.
function(vkt_add_chapter name)
  cmake_parse_arguments(ARG "OVERLAY" "" "SHADERS;SHARED_SHADERS" ${ARGN})
  if(ARG_OVERLAY)
    list(APPEND ARG_SHARED_SHADERS overlay/overlay.vert overlay/overlay.frag)
  endif()
  add_executable(${name} main.cpp)
  target_link_libraries(${name} PRIVATE vkt vkt_warnings)
  add_dependencies(${name} vkt_assets)
  list(TRANSFORM ARG_SHADERS PREPEND ${PROJECT_SOURCE_DIR}/shaders/${name}/)
  list(TRANSFORM ARG_SHARED_SHADERS PREPEND ${PROJECT_SOURCE_DIR}/shaders/common/)
  if(ARG_SHADERS OR ARG_SHARED_SHADERS)
    vkt_add_shaders(${name}_shaders ${name} ${ARG_SHADERS} ${ARG_SHARED_SHADERS})
    add_dependencies(${name} ${name}_shaders)
  endif()
  set_property(GLOBAL APPEND PROPERTY VKT_CHAPTERS ${name})
endfunction()
