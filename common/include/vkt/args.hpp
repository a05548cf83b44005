#pragma once
// The command line every chapter shares (see the book's "Running the chapters").
// Parsing is pure, so the unit tests can feed it any argument list.

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace vkt {

struct Options {
    bool headless = false;               // --headless: no window, even if a display exists
    bool offscreen = false;              // --offscreen: no surface at all, our own images only
    std::optional<uint32_t> frames;      // --frames N: stop after N frames
    uint32_t width = 800, height = 600;  // --size WxH
    std::string screenshot;              // --screenshot FILE.png: the last frame as a PNG
    bool benchmark = false;              // --benchmark: JSON timings on stdout
    std::string device;                  // --device NAME|INDEX
    std::optional<bool> validation;      // --validation / --no-validation (unset: on if installed)
    bool help = false;                   // --help
};

// Which flags a chapter accepts. A flag a chapter would silently ignore is
// refused instead: chapter 01 opens no device (no --device), chapters 01 and
// 02 draw nothing (no frame-loop flags).
enum class Flags {
    instance,   // chapter 01: --validation, --no-validation, --help
    device,     // chapter 02: those and --device
    frame_loop  // chapters 03 on: every flag
};

// A malformed or unknown argument; the runner prints it with the usage line and
// exits with status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// args excludes the program name.
Options parse_args(std::span<const char* const> args, Flags flags = Flags::frame_loop);

std::string usage_line(std::string_view program, Flags flags = Flags::frame_loop);
std::string help_text(std::string_view program, Flags flags = Flags::frame_loop);

}  // namespace vkt
