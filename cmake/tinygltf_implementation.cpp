// tinygltf's implementation, for a tinygltf that comes as a header only
// (vcpkg's): cmake/tinygltf.cmake compiles this file once into vkt_tinygltf.
// Debian's and Ubuntu's tinygltf is a compiled library, and this is not built.
//
// Its JSON library is included here by its installed name, nlohmann/json.hpp
// (tinygltf's own release says "json.hpp"); TINYGLTF_NO_STB_IMAGE and
// TINYGLTF_NO_STB_IMAGE_WRITE come from the target, as for every user.
#include <nlohmann/json.hpp>

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_JSON
#include <tiny_gltf.h>
