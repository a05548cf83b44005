# Which tinygltf the system has, told by what its header offers rather than by
# its version number (a distribution may patch either way). Debian 12 ships
# 2.7, Debian 13 2.9; the glTF loader (common/scene/src/gltf_files.cpp) reads
# every file through callbacks of its own, and the two differ there:
#
#   VKT_TINYGLTF_FILE_SIZE_CALLBACK   FsCallbacks has a fifth callback,
#                                     GetFileSizeInBytes (2.8 and later), which
#                                     tinygltf asks before it reads a file
#   VKT_TINYGLTF_FS_CALLBACKS_CHECKED SetFsCallbacks returns bool (2.9 and
#                                     later): false when it refused the
#                                     callbacks and kept its own file access
#   VKT_TINYGLTF_URI_CALLBACKS        URIs are %-decoded through a callback
#                                     (SetURICallbacks, 2.9 and later), which
#                                     lets the loader see each decoded URI:
#                                     2.9 itself skips one that decodes to a
#                                     NUL byte with only a warning
#
# Each is defined as 0 or 1 for the targets passed to vkt_use_tinygltf_api.
include(CheckCXXSourceCompiles)
include(CMakePushCheckState)

cmake_push_check_state(RESET)
set(CMAKE_REQUIRED_LIBRARIES TinyGLTF::TinyGLTF)
set(CMAKE_REQUIRED_QUIET ON)
check_cxx_source_compiles([[
#include <tiny_gltf.h>
int main() {
    tinygltf::FsCallbacks callbacks{};
    callbacks.GetFileSizeInBytes = nullptr;
    return callbacks.user_data == nullptr ? 0 : 1;
}]] VKT_TINYGLTF_FILE_SIZE_CALLBACK)
check_cxx_source_compiles([[
#include <tiny_gltf.h>
#include <type_traits>
#include <utility>
using Answer = decltype(std::declval<tinygltf::TinyGLTF&>().SetFsCallbacks(
    std::declval<tinygltf::FsCallbacks>()));
static_assert(std::is_same_v<Answer, bool>);
int main() { return 0; }]] VKT_TINYGLTF_FS_CALLBACKS_CHECKED)
check_cxx_source_compiles([[
#include <tiny_gltf.h>
int main() {
    tinygltf::TinyGLTF gltf;
    tinygltf::URICallbacks callbacks{};
    callbacks.decode = tinygltf::URIDecode;
    return gltf.SetURICallbacks(callbacks) ? 0 : 1;
}]] VKT_TINYGLTF_URI_CALLBACKS)
cmake_pop_check_state()

set(_vkt_file_size no)
set(_vkt_checked no)
set(_vkt_uri no)
if(VKT_TINYGLTF_URI_CALLBACKS)
  set(_vkt_uri yes)
endif()
if(VKT_TINYGLTF_FILE_SIZE_CALLBACK)
  set(_vkt_file_size yes)
endif()
if(VKT_TINYGLTF_FS_CALLBACKS_CHECKED)
  set(_vkt_checked yes)
endif()
message(STATUS "tinygltf ${TinyGLTF_VERSION}: FsCallbacks::GetFileSizeInBytes: ${_vkt_file_size}; "
               "SetFsCallbacks answers whether it took them: ${_vkt_checked}; "
               "URICallbacks: ${_vkt_uri}")

# vkt_use_tinygltf_api(<target>...): the two answers above, as 0 or 1.
function(vkt_use_tinygltf_api)
  foreach(target ${ARGN})
    target_compile_definitions(${target} PRIVATE
      VKT_TINYGLTF_FILE_SIZE_CALLBACK=$<BOOL:${VKT_TINYGLTF_FILE_SIZE_CALLBACK}>
      VKT_TINYGLTF_FS_CALLBACKS_CHECKED=$<BOOL:${VKT_TINYGLTF_FS_CALLBACKS_CHECKED}>
      VKT_TINYGLTF_URI_CALLBACKS=$<BOOL:${VKT_TINYGLTF_URI_CALLBACKS}>)
  endforeach()
endfunction()
