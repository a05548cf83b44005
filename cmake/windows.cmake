# Windows executables cross-built on Debian with MinGW-w64 (the toolchain is
# cmake/mingw-w64-x86_64.cmake; scripts/windows-build.sh builds everything and
# runs it under Wine). Included from the top-level CMakeLists.txt when the
# target is Windows, for the three dependencies whose Debian packages serve
# here only as headers:
#
#   Vulkan   Debian has the headers but no vulkan-1.lib import library for
#            MinGW, so volk (libvulkan-volk-dev) opens vulkan-1.dll at run
#            time: every file sees volk's function pointers in place of the
#            prototypes (VK_NO_PROTOTYPES, volk.h included first), and
#            common/core/src/windows/vulkan_loader.cpp loads them.
#   GLM      header-only.
#   tinygltf Debian ships it compiled for Linux; here its header's own
#            implementation is compiled into a small static library, as
#            cmake/tinygltf.cmake does for any header-only tinygltf.
#
# The other libraries (GLFW, libpng with zlib, libjpeg-turbo, Catch2) are
# built for the target from Debian's source packages into the prefix that
# VKT_MINGW_DEPS names, and found there by the same find_package calls as on
# Linux.
enable_language(C)  # volk.c

# The host's header-only packages, each linked alone into the build folder:
# putting /usr/include itself on a MinGW include path would mix glibc's
# headers into Windows code.
set(VKT_HOST_INCLUDE /usr/include CACHE PATH "Where the host's header-only packages are")
set(VKT_HOST_HEADERS ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${VKT_HOST_HEADERS})
foreach(entry vulkan vk_video volk.h volk.c glm tiny_gltf.h nlohmann)
  if(NOT EXISTS ${VKT_HOST_INCLUDE}/${entry})
    if(entry MATCHES "^vk_video$")
      continue()  # only in newer Vulkan headers
    endif()
    vkt_missing_dependency("${VKT_HOST_INCLUDE}/${entry}, a header-only dependency of the Windows build"
      APT "libvulkan-dev libvulkan-volk-dev libglm-dev libtinygltf-dev nlohmann-json3-dev"
      FEDORA "-" ARCH "-" ELSEWHERE "the same headers, named by -DVKT_HOST_INCLUDE=DIR")
  endif()
  file(CREATE_LINK ${VKT_HOST_INCLUDE}/${entry} ${VKT_HOST_HEADERS}/${entry} SYMBOLIC)
endforeach()

# Vulkan through volk.
add_library(vkt_volk STATIC ${VKT_HOST_HEADERS}/volk.c
                            ${PROJECT_SOURCE_DIR}/common/core/src/windows/vulkan_loader.cpp)
target_include_directories(vkt_volk SYSTEM PUBLIC ${VKT_HOST_HEADERS})
target_compile_definitions(vkt_volk PUBLIC VK_NO_PROTOTYPES)
add_library(vkt_vulkan INTERFACE)
target_link_libraries(vkt_vulkan INTERFACE vkt_volk)
target_compile_options(vkt_vulkan INTERFACE "$<$<COMPILE_LANGUAGE:CXX>:SHELL:-include volk.h>")
# Nothing calls into vulkan_loader.cpp by name (it starts volk before main), so
# the linker is told to keep it.
target_link_options(vkt_vulkan INTERFACE -Wl,--undefined=vkt_vulkan_loader_linked)
add_library(Vulkan::Vulkan ALIAS vkt_vulkan)
add_library(Vulkan::Headers ALIAS vkt_vulkan)

add_library(vkt_glm_headers INTERFACE)
target_include_directories(vkt_glm_headers SYSTEM INTERFACE ${VKT_HOST_HEADERS})
add_library(glm::glm ALIAS vkt_glm_headers)

# tinygltf: cmake/tinygltf.cmake compiles the header's implementation, as for
# any header-only tinygltf; here it finds the header among the host's.
set(VKT_TINYGLTF_INCLUDE_DIR ${VKT_HOST_HEADERS} CACHE PATH "tiny_gltf.h for the Windows build")
set(VKT_NLOHMANN_JSON_INCLUDE_DIR ${VKT_HOST_HEADERS} CACHE PATH "nlohmann/json.hpp for the Windows build")

# vkt_find_package looks for neither of these two (cmake/dependencies.cmake).
set(VKT_PROVIDED_PACKAGES Vulkan glm)
set(Vulkan_FOUND TRUE)
set(glm_FOUND TRUE)
