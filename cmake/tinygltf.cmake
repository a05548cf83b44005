# tinygltf as the chapters link it: TinyGLTF::TinyGLTF.
#
# Debian and Ubuntu ship tinygltf compiled, a shared library with a CMake
# package; find_package finds it and nothing below runs. vcpkg (and any system
# that packages only tiny_gltf.h) ships it header-only: then its implementation
# is compiled here, once, in cmake/tinygltf_implementation.cpp, with
# nlohmann/json for its JSON and without its stb_image loader and writer (vkt
# decodes pictures itself: common/scene/src/gltf_files.cpp sets the loader).
# The two TINYGLTF_NO_STB_* definitions reach every user of the header, since
# they change the TinyGLTF class itself.
find_package(TinyGLTF QUIET)
if(NOT TinyGLTF_FOUND AND NOT TARGET vkt_tinygltf)
  find_path(VKT_TINYGLTF_INCLUDE_DIR tiny_gltf.h)
  find_path(VKT_NLOHMANN_JSON_INCLUDE_DIR nlohmann/json.hpp)
  if(VKT_TINYGLTF_INCLUDE_DIR AND VKT_NLOHMANN_JSON_INCLUDE_DIR)
    add_library(vkt_tinygltf STATIC ${CMAKE_CURRENT_LIST_DIR}/tinygltf_implementation.cpp)
    target_include_directories(vkt_tinygltf SYSTEM PRIVATE ${VKT_TINYGLTF_INCLUDE_DIR}
                                                           ${VKT_NLOHMANN_JSON_INCLUDE_DIR})
    target_compile_definitions(vkt_tinygltf PRIVATE TINYGLTF_NO_STB_IMAGE TINYGLTF_NO_STB_IMAGE_WRITE
                                                    $<$<CXX_COMPILER_ID:MSVC>:_CRT_SECURE_NO_WARNINGS>)
    # What the chapters link: an imported target, as Debian's is, so that a
    # configure-time check of the header (cmake/tinygltf_api.cmake) can use it
    # too; there the compiled part does not exist and is left out.
    add_library(TinyGLTF::TinyGLTF INTERFACE IMPORTED)
    set_target_properties(TinyGLTF::TinyGLTF PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${VKT_TINYGLTF_INCLUDE_DIR}"
      INTERFACE_COMPILE_DEFINITIONS "TINYGLTF_NO_STB_IMAGE;TINYGLTF_NO_STB_IMAGE_WRITE"
      INTERFACE_LINK_LIBRARIES "$<TARGET_NAME_IF_EXISTS:vkt_tinygltf>")
    set(TinyGLTF_FOUND TRUE)
    message(STATUS "tinygltf: header-only (${VKT_TINYGLTF_INCLUDE_DIR}), compiled here")
  endif()
endif()
