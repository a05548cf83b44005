// libFuzzer target: the command line every chapter shares (vkt/frame/args.hpp).
// The input is the argument list, arguments separated by NUL bytes; its first
// byte picks which flags the "chapter" accepts (01's, 02's or a drawing
// chapter's). The chapter's own flags are one of each kind, with ranges like
// the real chapters' (a number whose range starts at 0, as 14's --warmup).
//
// The contract: parse_args returns options that keep every promise below, or
// throws UsageError (which the runner prints with exit status 2). Any other
// exception, a broken promise, a crash or a sanitizer report is a finding.
#include "vkt/frame/args.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

const std::vector<vkt::OptionSpec>& chapter_options() {
    static const std::vector<vkt::OptionSpec> options = {
        {.name = "--lights",
         .type = vkt::OptionType::integer,
         .default_value = "64",
         .min = 1,
         .max = 65536},
        {.name = "--warmup",
         .type = vkt::OptionType::number,
         .default_value = "0",
         .min = 0,
         .max = 60},
        {.name = "--speed", .type = vkt::OptionType::number, .min = 0.1, .max = 50},
        {.name = "--shade",
         .type = vkt::OptionType::choice,
         .default_value = "fragment",
         .choices = {"fragment", "compute"}},
        {.name = "--model", .type = vkt::OptionType::text},
    };
    return options;
}

void require(bool promise) {
    if (!promise) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const vkt::Flags flags = data[0] % 3 == 0   ? vkt::Flags::instance
                             : data[0] % 3 == 1 ? vkt::Flags::device
                                                : vkt::Flags::frame_loop;
    // Arguments: the rest, split at NUL bytes (as the kernel hands argv over).
    std::vector<std::string> words(1);
    for (size_t i = 1; i < size; ++i) {
        if (data[i] == 0)
            words.emplace_back();
        else
            words.back() += char(data[i]);
    }
    std::vector<const char*> argv;
    for (const std::string& word : words) argv.push_back(word.c_str());

    const auto& specs = chapter_options();
    const std::span<const vkt::OptionSpec> own =
        flags == vkt::Flags::frame_loop ? std::span(specs) : std::span<const vkt::OptionSpec>{};
    vkt::Options options;
    try {
        options = vkt::parse_args(argv, flags, own);
    } catch (const vkt::UsageError&) {
        return 0;
    }
    // What the runner and the chapters rely on once parsing succeeded.
    require(options.width >= 1 && options.width <= 16384);
    require(options.height >= 1 && options.height <= 16384);
    require(!options.frames || *options.frames >= 1);
    require(options.screenshot.empty() || options.screenshot.ends_with(".png"));
    require(!options.offscreen || options.headless);
    if (flags != vkt::Flags::frame_loop)
        require(!options.headless && !options.frames && options.screenshot.empty() &&
                !options.benchmark);
    if (flags == vkt::Flags::instance) require(options.device.empty());
    for (const vkt::OptionSpec& spec : own) {
        if (!options.has(spec.name)) {
            require(spec.default_value.empty());
            continue;
        }
        // Every value reads back, within its range: a chapter calls these
        // without a try (a throw here would end it as "error: stod").
        switch (spec.type) {
            case vkt::OptionType::integer: {
                const int64_t value = options.integer(spec.name);
                require(double(value) >= spec.min && double(value) <= spec.max);
                break;
            }
            case vkt::OptionType::number: {
                const double value = options.number(spec.name);
                require(std::isfinite(value) && value >= spec.min && value <= spec.max);
                break;
            }
            case vkt::OptionType::choice: {
                bool known = false;
                for (const std::string& choice : spec.choices)
                    known = known || choice == options.text(spec.name);
                require(known);
                break;
            }
            case vkt::OptionType::text:
                require(!options.text(spec.name).empty());
                break;
        }
    }
    // The usage line and --help text for the same flags never fail.
    require(!vkt::usage_line("fuzz", flags, own).empty());
    require(!vkt::help_text("fuzz", flags, own).empty());
    return 0;
}
