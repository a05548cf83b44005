// The Windows build's tinygltf (cmake/windows.cmake): Debian ships tinygltf
// compiled for Linux only, so its header's own implementation is compiled
// here, once, into a static library. The Linux build uses Debian's library
// and never compiles this file.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
