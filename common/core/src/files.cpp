#include "vkt/core/files.hpp"

#include "vkt/core/check.hpp"

#include <fstream>
#include <string>

namespace vkt {

std::filesystem::path executable_dir() {
    std::error_code error;
    auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::current_path() : self.parent_path();
}

std::filesystem::path shader_path(std::string_view chapter, std::string_view glsl_file) {
    return executable_dir().parent_path() / "shaders" / chapter / (std::string(glsl_file) + ".spv");
}

std::filesystem::path asset_path(std::string_view name) {
    return executable_dir().parent_path() / "assets" / name;
}

std::vector<char> read_file(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw Error("cannot open " + path.string());
    std::vector<char> bytes(static_cast<size_t>(file.tellg()));
    file.seekg(0);
    if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw Error("cannot read " + path.string());
    return bytes;
}

}  // namespace vkt
