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
// bytes, past the 1 GiB limit for one file"; and "FILE: its size reads as 0
// bytes, yet it holds data" for a file of /proc or /sys.
std::vector<char> read_file(const std::filesystem::path& path);

// The size of the file read_file would read, after the same checks (and the
// same messages); nothing is read.
uintmax_t readable_file_size(const std::filesystem::path& path);

// The first `count` bytes of a file (fewer if it is shorter): what a loader
// looks at before it reads a file whole, so that a gigabyte that is not a
// model or an image is refused at once. Read whatever size the file system
// reports (a file of /proc reports 0). Throws "cannot open FILE", and
// read_file's refusals of a directory, a device, a file past 1 GiB.
std::vector<char> read_file_start(const std::filesystem::path& path, size_t count);

// Where `uri`, a relative file name that a file in `folder` contains (a glTF
// buffer or image), points: `folder / uri` with symbolic links and ".."
// resolved, and only if that lies inside `folder`. A model downloaded from
// anywhere must not make a chapter read files outside its own folder
// (chapter 10). Throws Error naming the URI when it is empty, holds a control
// character, is absolute (or has a drive), or leads out of the folder. The
// file need not exist.
std::filesystem::path resolve_inside(const std::filesystem::path& folder, std::string_view uri);

// A file's path as a message shows it: as it is where that is plain; in
// double quotes where it is not (a control character, a quote, white space
// at either end), each control character escaped (\n, \t, \r, else \xHH),
// and a quote or a backslash after a backslash. So a name's trailing space
// is seen, and an escape sequence in a name never reaches the terminal:
// "models/car.gltf " and "\x1b[31mred.gltf".
std::string shown_path(const std::filesystem::path& path);

// `text` fit for a one-line message: control characters as %XX (a NUL byte
// shows as %00) and at most `limit` characters, then "...".
std::string printable(std::string_view text, size_t limit = 120);

}  // namespace vkt
