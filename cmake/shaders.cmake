# vkt_add_shaders(<target> <chapter> <glsl files...>)
# Compiles each GLSL file to ${VKT_SHADER_OUTPUT_DIR}/<chapter>/<file>.spv at build
# time. glslangValidator writes a depfile, so editing an #included file rebuilds
# exactly the SPIR-V that includes it, and nothing of other chapters.
function(vkt_add_shaders target chapter)
  set(outputs)
  foreach(src IN LISTS ARGN)
    get_filename_component(abs ${src} ABSOLUTE)
    get_filename_component(name ${src} NAME)
    set(out ${VKT_SHADER_OUTPUT_DIR}/${chapter}/${name}.spv)
    set(dep ${CMAKE_CURRENT_BINARY_DIR}/${chapter}_${name}.d)
    add_custom_command(
      OUTPUT ${out}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${VKT_SHADER_OUTPUT_DIR}/${chapter}
      COMMAND ${GLSLANG_VALIDATOR} --quiet -V --target-env vulkan1.3
              -I${PROJECT_SOURCE_DIR}/shaders/common --depfile ${dep} -o ${out} ${abs}
      DEPENDS ${abs}
      DEPFILE ${dep}
      COMMENT "GLSL -> SPIR-V ${chapter}/${name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${target} DEPENDS ${outputs})
endfunction()
