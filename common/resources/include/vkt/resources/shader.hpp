#pragma once
// Loading SPIR-V into a shader module: the tidy form of chapter 04.

#include "vkt/core/owned.hpp"

#include <string_view>

namespace vkt {

// Reads <bin>/../shaders/<chapter>/<glsl_file>.spv, checks that it is SPIR-V
// (a whole number of words, starting with the magic number 0x07230203), and
// makes a shader module of it. Throws Error naming the file otherwise.
ShaderModule load_shader(VkDevice device, std::string_view chapter, std::string_view glsl_file);

}  // namespace vkt
