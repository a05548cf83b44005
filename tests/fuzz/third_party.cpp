// tinygltf, compiled into the fuzzers with coverage and ASan (see
// CMakeLists.txt here): the same header Debian's shared library was built
// from, with its implementation switched on. The stb_image functions it
// calls come from Debian's libstb, as they do for the shared library.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
