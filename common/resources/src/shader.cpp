#include "vkt/resources/shader.hpp"

#include "vkt/core/check.hpp"
#include "vkt/core/files.hpp"

#include <cstring>
#include <vector>

namespace vkt {

ShaderModule load_shader(VkDevice device, std::string_view chapter, std::string_view glsl_file) {
    const auto path = shader_path(chapter, glsl_file);
    std::vector<char> code = read_file(path);
    uint32_t magic = 0;
    if (code.size() >= 4) std::memcpy(&magic, code.data(), 4);
    if (code.size() % 4 != 0 || magic != 0x07230203)
        throw Error(shown_path(path) + " is not SPIR-V (rebuild the chapter's shaders)");
    // pCode must be 4-byte aligned; a vector<char>'s storage from operator new is.
    VkShaderModuleCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
        .codeSize = code.size(),
        .pCode = reinterpret_cast<const uint32_t*>(code.data()),
    };
    VkShaderModule module;
    VKT_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
    return ShaderModule(device, module);
}

}  // namespace vkt
