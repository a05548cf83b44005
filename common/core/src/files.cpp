#include "vkt/core/files.hpp"

#include "vkt/core/check.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

// Where the running program is: each system has its own call (Linux a link in
// /proc). Where it fails, the current folder stands in.
#if defined(_WIN32)
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#elif defined(__APPLE__)
#include <mach-o/dyld.h>
#endif

namespace vkt {

std::filesystem::path executable_dir() {
#if defined(_WIN32)
    std::wstring self(32768, L'\0');  // the longest path Windows has
    const DWORD length = GetModuleFileNameW(nullptr, self.data(), DWORD(self.size()));
    if (length == 0 || length >= self.size()) return std::filesystem::current_path();
    self.resize(length);
    return std::filesystem::path(self).parent_path();
#elif defined(__APPLE__)
    uint32_t size = 0;
    _NSGetExecutablePath(nullptr, &size);  // says how long the path is
    std::string self(size, '\0');
    if (_NSGetExecutablePath(self.data(), &size) != 0) return std::filesystem::current_path();
    self.resize(std::strlen(self.c_str()));
    std::error_code error;
    const auto real = std::filesystem::canonical(self, error);
    return error ? std::filesystem::current_path() : real.parent_path();
#else
    std::error_code error;
    auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    return error ? std::filesystem::current_path() : self.parent_path();
#endif
}

std::filesystem::path shader_path(std::string_view chapter, std::string_view glsl_file) {
    return executable_dir().parent_path() / "shaders" / chapter / (std::string(glsl_file) + ".spv");
}

std::filesystem::path asset_path(std::string_view name) {
    return executable_dir().parent_path() / "assets" / name;
}

uintmax_t readable_file_size(const std::filesystem::path& path) {
    // A directory opens as a stream whose end is at 2^63 - 1 (std::bad_alloc,
    // or an abort under AddressSanitizer, and no file named); a FIFO would
    // block and /dev/zero never ends. So: what is it, and how large?
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (error || !std::filesystem::exists(status)) throw Error("cannot open " + path.string());
    if (std::filesystem::is_directory(status))
        throw Error(path.string() + ": is a directory, not a file");
    if (!std::filesystem::is_regular_file(status))
        throw Error(path.string() + ": is not a regular file");
    const uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw Error("cannot open " + path.string());
    if (size > max_file_bytes)
        throw Error(path.string() + ": is " + std::to_string(size) +
                    " bytes, past the 1 GiB limit for one file");
    return size;
}

std::vector<char> read_file(const std::filesystem::path& path) {
    const uintmax_t size = readable_file_size(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open " + path.string());
    std::vector<char> bytes(static_cast<size_t>(size));
    if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw Error("cannot read " + path.string());
    return bytes;
}

std::vector<char> read_file_start(const std::filesystem::path& path, size_t count) {
    const uintmax_t size = readable_file_size(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open " + path.string());
    std::vector<char> bytes(static_cast<size_t>(std::min<uintmax_t>(size, count)));
    if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw Error("cannot read " + path.string());
    return bytes;
}

std::string printable(std::string_view text, size_t limit) {
    std::string out;
    for (const char c : text) {
        if (out.size() >= limit) return out + "...";
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            const char* hex = "0123456789ABCDEF";
            out += {'%', hex[byte >> 4], hex[byte & 15]};
        } else {
            out += c;
        }
    }
    return out;
}

std::filesystem::path resolve_inside(const std::filesystem::path& folder, std::string_view uri) {
    namespace fs = std::filesystem;
    const std::string named = "URI \"" + printable(uri) + "\"";
    if (uri.empty()) throw Error("an empty URI names no file");
    for (const char c : uri)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            throw Error(named + " is not a file name: it holds a control character");
    const fs::path relative(uri);
    if (relative.has_root_name() || relative.has_root_directory())
        throw Error(named + " is an absolute path: a model may name only files in its own folder");
    // Resolve both sides the same way (symbolic links, "..", "."), then ask
    // whether the file's path starts with the folder's.
    std::error_code error;
    const fs::path root = fs::weakly_canonical(fs::absolute(folder, error), error);
    fs::path target = error ? fs::path() : fs::weakly_canonical(root / relative, error);
    if (error) throw Error(named + ": " + error.message());
    const fs::path inside = target.lexically_relative(root);
    if (inside.empty() || *inside.begin() == "..")
        throw Error(named + " leads out of the model's folder (" + root.string() +
                    "): a model may name only files in its own folder");
    return target;
}

}  // namespace vkt
