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
    if (error || !std::filesystem::exists(status)) throw Error("cannot open " + shown_path(path));
    if (std::filesystem::is_directory(status))
        throw Error(shown_path(path) + ": is a directory, not a file");
    if (!std::filesystem::is_regular_file(status))
        throw Error(shown_path(path) + ": is not a regular file");
    const uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw Error("cannot open " + shown_path(path));
    if (size > max_file_bytes)
        throw Error(shown_path(path) + ": is " + std::to_string(size) +
                    " bytes, past the 1 GiB limit for one file");
    return size;
}

std::vector<char> read_file(const std::filesystem::path& path) {
    const uintmax_t size = readable_file_size(path);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open " + shown_path(path));
    std::vector<char> bytes(static_cast<size_t>(size));
    if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw Error("cannot read " + shown_path(path));
    // A file of /proc or /sys says it is 0 bytes long and yet holds some:
    // what it holds is not known until it is read, so it is not read.
    if (size == 0 && file.peek() != std::ifstream::traits_type::eof())
        throw Error(shown_path(path) +
                    ": its size reads as 0 bytes, yet it holds data (a file of /proc or /sys?): "
                    "only a file whose size is known is read");
    return bytes;
}

std::vector<char> read_file_start(const std::filesystem::path& path, size_t count) {
    (void)readable_file_size(path);  // its checks: no directory, no device
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open " + shown_path(path));
    // Up to `count` bytes, whatever size the file claims (one of /proc
    // claims 0): its first bytes are what they are.
    std::vector<char> bytes(count);
    file.read(bytes.data(), static_cast<std::streamsize>(count));
    if (file.bad()) throw Error("cannot read " + shown_path(path));
    bytes.resize(static_cast<size_t>(file.gcount()));
    return bytes;
}

std::string shown_path(const std::filesystem::path& path) {
    std::string text = path.string();
    const auto control = [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; };
    const bool plain =
        !text.empty() && text.front() != ' ' && text.back() != ' ' &&
        std::none_of(text.begin(), text.end(), [&](char c) { return control(c) || c == '"'; });
    if (plain) return text;
    std::string out = "\"";
    for (const char c : text) {
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else if (control(c)) {
            const char* hex = "0123456789abcdef";
            const auto byte = static_cast<unsigned char>(c);
            out += {'\\', 'x', hex[byte >> 4], hex[byte & 15]};
        } else {
            if (c == '"' || c == '\\') out += '\\';
            out += c;
        }
    }
    return out + "\"";
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
        throw Error(named + " leads out of the model's folder (" + shown_path(root) +
                    "): a model may name only files in its own folder");
    return target;
}

}  // namespace vkt
