#pragma once
// Finding and reading the files a chapter needs at run time: taught in
// chapter 04 (its SPIR-V); chapters 09 and 10 read images and glTF with it.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

// The folder that holds the running executable (build/<preset>/bin).
std::filesystem::path executable_dir();

// Where the build put a chapter's SPIR-V: <bin>/../shaders/<chapter>/<file>.spv.
std::filesystem::path shader_path(std::string_view chapter, std::string_view glsl_file);

// Where the build copied the repository's assets/: <bin>/../assets/<name>.
std::filesystem::path asset_path(std::string_view name);

// The most read_file reads from one file: 1 GiB. Far more than any asset here,
// and below 2^31, so a length still fits the int that tinygltf takes
// (chapter 10).
inline constexpr uintmax_t max_file_bytes = uintmax_t(1) << 30;

// The whole file; throws Error naming the file when it cannot be read. It
// looks before it reads, so that a path a user typed (or a file named) cannot
// make it allocate what the file system reports for a directory or a device:
// "cannot open FILE" (missing or unreadable), "FILE: is a directory, not a
// file", "FILE: is not a regular file" (a device, a pipe) and "FILE: is N
// bytes, past the 1 GiB limit for one file".
std::vector<char> read_file(const std::filesystem::path& path);

// The size of the file read_file would read, after the same checks (and the
// same messages); nothing is read.
uintmax_t readable_file_size(const std::filesystem::path& path);

// The first `count` bytes of a file (fewer if it is shorter): what a loader
// looks at before it reads a file whole, so that a gigabyte that is not a
// model or an image is refused at once. Throws "cannot open FILE".
std::vector<char> read_file_start(const std::filesystem::path& path, size_t count);

// Where `uri`, a relative file name that a file in `folder` contains (a glTF
// buffer or image), points: `folder / uri` with symbolic links and ".."
// resolved, and only if that lies inside `folder`. A model downloaded from
// anywhere must not make a chapter read files outside its own folder
// (chapter 10). Throws Error naming the URI when it is empty, holds a control
// character, is absolute (or has a drive), or leads out of the folder. The
// file need not exist.
std::filesystem::path resolve_inside(const std::filesystem::path& folder, std::string_view uri);

// `text` fit for a one-line message: control characters as %XX (a NUL byte
// shows as %00) and at most `limit` characters, then "...".
std::string printable(std::string_view text, size_t limit = 120);

}  // namespace vkt
