#pragma once
// The command line every chapter shares, from chapter 01 on (--validation); see
// README.md's "Running a chapter" and the book's "Running headless" appendix.
// Parsing is pure, so the unit tests can feed it any argument list.

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace vkt {

// A flag of a chapter's own (chapter 06 on): declared in its ChapterSpec, parsed
// and checked by the same parser as the shared flags, listed by --help.
enum class OptionType {
    integer,  // a whole number within [min, max]
    number,   // a real number within [min, max]
    choice,   // one of `choices`
    text,     // any non-empty text (a file name, say)
    bytes,    // a size: 512M, 2G (vkt::parse_byte_count), within [min, max] bytes;
              // Options::integer gives it in bytes
};

struct OptionSpec {
    std::string name;  // "--lights"
    OptionType type = OptionType::text;
    std::string value_name;            // shown in the usage line: "N", "FILE", "NAME"
    std::string help;                  // one line
    std::string default_value;         // as it would be typed; empty: unset unless given
    double min = 0, max = 0;           // integer and number: the accepted range
    std::vector<std::string> choices;  // choice: the accepted words
};

struct Options {
    bool headless = false;               // --headless: no window, even if a display exists
    bool offscreen = false;              // --offscreen: no surface at all, our own images only
    std::optional<uint32_t> frames;      // --frames N: stop after N frames
    uint32_t width = 800, height = 600;  // --size WxH
    std::string screenshot;              // --screenshot FILE.png: the last frame as a PNG
    bool benchmark = false;              // --benchmark: JSON timings on stdout
    bool copy_to_swapchain = false;      // --copy-to-swapchain: never draw into its images
    std::string device;                  // --device NAME|INDEX
    std::optional<bool> validation;      // --validation / --no-validation (unset: on if installed)
    bool help = false;                   // --help

    // The chapter's own flags (see OptionSpec): the value given, or the default.
    std::map<std::string, std::string, std::less<>> values;
    bool has(std::string_view name) const { return values.contains(name); }
    // Each throws std::logic_error for a name the chapter did not declare or
    // that has no value: a bug in the chapter, not bad input.
    const std::string& text(std::string_view name) const;
    int64_t integer(std::string_view name) const;
    double number(std::string_view name) const;
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
// chapter_options are the chapter's own flags; their defaults are filled in.
Options parse_args(std::span<const char* const> args, Flags flags = Flags::frame_loop,
                   std::span<const OptionSpec> chapter_options = {});

// --max-memory SIZE, for the chapters that load a file the reader chooses
// (09's texture, 10's model): the most memory the file may make the chapter
// spend, decoded, staged and on the GPU (vkt/core/memory_budget.hpp). One
// definition, so that both chapters take and explain it alike.
OptionSpec max_memory_option();

std::string usage_line(std::string_view program, Flags flags = Flags::frame_loop,
                       std::span<const OptionSpec> chapter_options = {});
std::string help_text(std::string_view program, Flags flags = Flags::frame_loop,
                      std::span<const OptionSpec> chapter_options = {});

}  // namespace vkt
