#pragma once
// Finding and reading the files a chapter needs at run time.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace vkt {

// The folder that holds the running executable (build/<preset>/bin).
std::filesystem::path executable_dir();

// Where the build put a chapter's SPIR-V: <bin>/../shaders/<chapter>/<file>.spv.
std::filesystem::path shader_path(std::string_view chapter, std::string_view glsl_file);

// Where the build copied the repository's assets/: <bin>/../assets/<name>.
std::filesystem::path asset_path(std::string_view name);

// The whole file; throws Error naming the file when it cannot be read.
std::vector<char> read_file(const std::filesystem::path& path);

}  // namespace vkt
