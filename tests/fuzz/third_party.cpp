// tinygltf and stb_image, compiled into the fuzzers with coverage and ASan
// (see CMakeLists.txt here): the same headers Debian's shared libraries were
// built from, with their implementations switched on.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
#undef STB_IMAGE_IMPLEMENTATION  // tiny_gltf.h includes stb_image.h again

#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
