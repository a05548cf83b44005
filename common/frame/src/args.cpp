#include "vkt/frame/args.hpp"

#include "vkt/core/memory_budget.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace vkt {

namespace {

// A whole, positive decimal number that fits in 32 bits, or nothing.
std::optional<uint32_t> parse_positive(std::string_view text) {
    uint64_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value == 0 ||
        value > std::numeric_limits<uint32_t>::max())
        return std::nullopt;
    return static_cast<uint32_t>(value);
}

// The shared flags, each written once: the parser, the usage line and the
// help text all read this table.
struct SharedFlag {
    std::string_view name;
    std::string_view value;  // what its value is called ("N", "WxH"); empty: a switch
    Flags from;              // the first kind of chapter that takes it
    bool or_previous;        // the usage line shows it as the previous flag's alternative
    std::string_view help;   // lines joined by '\n'
    // Stores the value (empty for a switch), or throws UsageError saying why not.
    void (*apply)(Options&, std::string_view value);
};

// Before the 32-bit limit: an upper bound for any device; the runner also
// checks the chosen device's maxImageDimension2D, which may be as small as 4096.
constexpr uint32_t max_side = 16384;

const SharedFlag shared_flags[] = {
    {"--headless", "", Flags::frame_loop, false,
     "no window: present to VK_EXT_headless_surface, or render\noffscreen where the device "
     "cannot present to it (also the\nchoice when there is no display or no window can open)",
     [](Options& o, std::string_view) { o.headless = true; }},
    {"--offscreen", "", Flags::frame_loop, true,
     "no surface at all: render into our own images only",
     [](Options& o, std::string_view) {
         o.headless = true;  // offscreen has no window either
         o.offscreen = true;
     }},
    {"--frames", "N", Flags::frame_loop, false,
     "stop after N frames; time is then frame index / 60 s\n(headless default: 60 frames)",
     [](Options& o, std::string_view text) {
         o.frames = parse_positive(text);
         if (!o.frames)
             throw UsageError("--frames wants a whole number of at least 1, not '" +
                              std::string(text) + "'");
     }},
    {"--size", "WxH", Flags::frame_loop, false,
     "size of the window or the headless image (default 800x600)",
     [](Options& o, std::string_view text) {
         const auto x = text.find('x');
         const auto w =
             x == std::string_view::npos ? std::nullopt : parse_positive(text.substr(0, x));
         const auto h =
             x == std::string_view::npos ? std::nullopt : parse_positive(text.substr(x + 1));
         if (!w || !h || *w > max_side || *h > max_side)
             throw UsageError("--size wants WIDTHxHEIGHT, each 1.." + std::to_string(max_side) +
                              ", not '" + std::string(text) + "'");
         o.width = *w;
         o.height = *h;
     }},
    {"--screenshot", "FILE.png", Flags::frame_loop, false,
     "write the last frame, as presented, as a PNG",
     [](Options& o, std::string_view text) {
         if (!text.ends_with(".png") || text.size() == 4)
             throw UsageError("--screenshot writes a PNG: give a file name ending in .png, not '" +
                              std::string(text) + "'");
         o.screenshot = text;
     }},
    {"--benchmark", "", Flags::frame_loop, false, "print CPU and GPU frame times as JSON on stdout",
     [](Options& o, std::string_view) { o.benchmark = true; }},
    {"--copy-to-swapchain", "", Flags::frame_loop, false,
     "draw into our own image and copy it into the swapchain\nimage (default: draw straight "
     "into the swapchain image\nwhere its format allows)",
     [](Options& o, std::string_view) { o.copy_to_swapchain = true; }},
    {"--device", "NAME|INDEX", Flags::device, false,
     "use this physical device (index, or part of its name)",
     [](Options& o, std::string_view text) {
         if (text.empty()) throw UsageError("--device wants a name or an index");
         o.device = text;
     }},
    {"--validation", "", Flags::instance, false,
     "require the Khronos validation layer, with synchronisation\nvalidation; any warning or "
     "error makes the exit status 1",
     [](Options& o, std::string_view) { o.validation = true; }},
    {"--no-validation", "", Flags::instance, true,
     "do not load the validation layer\n(default: validation on when the layer is installed)",
     [](Options& o, std::string_view) { o.validation = false; }},
    {"--help", "", Flags::instance, false, "this text",
     [](Options& o, std::string_view) { o.help = true; }},
};

// Whether a chapter of kind `flags` takes a flag first taken by `from`.
bool takes(Flags flags, Flags from) {
    return static_cast<int>(flags) >= static_cast<int>(from);
}

const SharedFlag* find_shared(std::string_view name) {
    if (name == "-h") name = "--help";
    for (const SharedFlag& flag : shared_flags)
        if (flag.name == name) return &flag;
    return nullptr;
}

// "  --flag VALUE", then its help in a column of its own: beside the flag, or
// below it where the flag is too wide; further lines of help below.
std::string help_entry(std::string_view name, std::string_view value, std::string_view help) {
    constexpr size_t column = 23;
    std::string text = "  ";
    text.append(name);
    if (!value.empty()) text.append(" ").append(value);
    if (text.size() < column)
        text.append(column - text.size(), ' ');
    else
        text.append("\n").append(column, ' ');
    for (char c : help) {
        text += c;
        if (c == '\n') text.append(column, ' ');
    }
    text += '\n';
    return text;
}

std::string format_number(double value) {
    char text[32];
    // 15 significant digits: every whole number a flag takes prints in full
    // (plain %g would write 268435456 as 2.68435e+08).
    std::snprintf(text, sizeof text, "%.15g", value);
    return text;
}

std::string joined(const std::vector<std::string>& words, const char* separator) {
    std::string out;
    for (const auto& word : words) out += (out.empty() ? "" : separator) + word;
    return out;
}

// Checks one value of a chapter option; returns it as it will be stored.
std::string check_option_value(const OptionSpec& spec, std::string_view text) {
    std::string given(text);  // not const: returned, so moved
    switch (spec.type) {
        case OptionType::integer: {
            int64_t value = 0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc{} || end != text.data() + text.size() || text.empty() ||
                double(value) < spec.min || double(value) > spec.max)
                throw UsageError(spec.name + " wants a whole number from " +
                                 format_number(spec.min) + " to " + format_number(spec.max) +
                                 ", not '" + given + "'");
            return std::to_string(value);
        }
        case OptionType::number: {
            double value = 0;
            auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error != std::errc{} || end != text.data() + text.size() || text.empty() ||
                !std::isfinite(value) || value < spec.min || value > spec.max)
                throw UsageError(spec.name + " wants a number from " + format_number(spec.min) +
                                 " to " + format_number(spec.max) + ", not '" + given + "'");
            return given;
        }
        case OptionType::choice:
            for (const auto& choice : spec.choices)
                if (choice == text) return given;
            throw UsageError(spec.name + " wants one of " + joined(spec.choices, ", ") + ", not '" +
                             given + "'");
        case OptionType::bytes: {
            const std::optional<uint64_t> value = parse_byte_count(text);
            if (!value || double(*value) < spec.min || double(*value) > spec.max)
                throw UsageError(
                    spec.name + " wants a size from " + byte_count_text(uint64_t(spec.min)) +
                    " to " + byte_count_text(uint64_t(spec.max)) +
                    " (a number of bytes, or with K, M, G: 512M, 4G), not '" + given + "'");
            return std::to_string(*value);
        }
        case OptionType::text:
        default:
            if (text.empty()) throw UsageError(spec.name + " needs a value");
            return given;
    }
}

std::string option_value_name(const OptionSpec& spec) {
    if (!spec.value_name.empty()) return spec.value_name;
    if (spec.type == OptionType::choice) return joined(spec.choices, "|");
    if (spec.type == OptionType::bytes) return "SIZE";
    return spec.type == OptionType::text ? "TEXT" : "N";
}

}  // namespace

const std::string& Options::text(std::string_view name) const {
    auto found = values.find(name);
    if (found == values.end())
        throw std::logic_error("chapter option " + std::string(name) + " has no value");
    return found->second;
}

// Both read the value with from_chars, as the check that let it in did
// (std::stod would refuse a subnormal such as 4e-320 that the check accepted).
int64_t Options::integer(std::string_view name) const {
    const std::string& value = text(name);
    int64_t out = 0;
    std::from_chars(value.data(), value.data() + value.size(), out);
    return out;
}

double Options::number(std::string_view name) const {
    const std::string& value = text(name);
    double out = 0;
    std::from_chars(value.data(), value.data() + value.size(), out);
    return out;
}

Options parse_args(std::span<const char* const> args, Flags flags,
                   std::span<const OptionSpec> chapter_options) {
    Options options;
    for (const auto& spec : chapter_options)
        if (!spec.default_value.empty())
            options.values[spec.name] = check_option_value(spec, spec.default_value);
    bool said_headless = false;
    for (size_t i = 0; i < args.size(); ++i) {
        std::string_view arg = args[i];
        // Accept both "--frames 10" and "--frames=10".
        std::string_view flag = arg;
        std::optional<std::string_view> inline_value;
        if (auto eq = arg.find('='); arg.starts_with("--") && eq != std::string_view::npos) {
            flag = arg.substr(0, eq);
            inline_value = arg.substr(eq + 1);
        }
        auto value = [&]() -> std::string_view {
            if (inline_value) return *inline_value;
            if (i + 1 >= args.size()) throw UsageError(std::string(flag) + " needs a value");
            // "--device --offscreen" forgot the device: it must not take the
            // next flag as its value. A value that does begin with "--" can
            // still be given inline, "--device=--odd".
            const std::string_view next = args[i + 1];
            if (next.starts_with("--") || next == "-h")
                throw UsageError(std::string(flag) + " needs a value, not the flag '" +
                                 std::string(next) + "' (write " + std::string(flag) + "=" +
                                 std::string(next) + " if that is the value)");
            return args[++i];
        };
        auto no_value = [&] {
            if (inline_value) throw UsageError(std::string(flag) + " takes no value");
        };

        if (const SharedFlag* shared = find_shared(flag)) {
            if (!takes(flags, shared->from))
                throw UsageError(
                    std::string(flag) + " is not used by this chapter: " +
                    (shared->from == Flags::device ? "it opens no device" : "it draws nothing"));
            if (shared->value.empty()) no_value();
            shared->apply(options, shared->value.empty() ? std::string_view{} : value());
            said_headless = said_headless || shared->name == "--headless";
        } else {
            const OptionSpec* spec = nullptr;
            for (const auto& candidate : chapter_options)
                if (candidate.name == flag) spec = &candidate;
            // The runner offers --overlay only to chapters with a settings
            // panel; elsewhere say why rather than "unknown".
            if (!spec && flag == "--overlay")
                throw UsageError("--overlay is not used by this chapter: it has no settings panel");
            if (!spec) throw UsageError("unknown argument '" + std::string(arg) + "'");
            options.values[spec->name] = check_option_value(*spec, value());
        }
    }
    // Alternatives, not a combination: which one was meant cannot be guessed.
    if (said_headless && options.offscreen)
        throw UsageError(
            "--headless and --offscreen are alternatives: give one (--offscreen renders with no "
            "surface at all, --headless presents to a headless surface)");
    return options;
}

OptionSpec max_memory_option() {
    return {.name = "--max-memory",
            .type = OptionType::bytes,
            .value_name = "SIZE",
            .help =
                "the most memory the file may make this chapter use, decoded, staged and "
                "on the GPU (512M, 4G)",
            .default_value = "1G",  // vkt::default_max_memory
            .min = double(uint64_t(16) << 20),
            .max = double(uint64_t(1) << 40)};
}

std::string usage_line(std::string_view program, Flags flags,
                       std::span<const OptionSpec> chapter_options) {
    std::string line = "usage: " + std::string(program);
    std::string group;  // "[--headless | --offscreen]": a flag and its alternatives
    auto close_group = [&] {
        if (!group.empty()) line.append(" [").append(group).append("]");
        group.clear();
    };
    for (const SharedFlag& flag : shared_flags) {
        if (!takes(flags, flag.from)) continue;
        std::string shown(flag.name);
        if (!flag.value.empty()) shown.append(" ").append(flag.value);
        if (!flag.or_previous) close_group();
        if (!group.empty()) group += " | ";
        group += shown;
    }
    close_group();
    for (const auto& spec : chapter_options)
        line += " [" + spec.name + " " + option_value_name(spec) + "]";
    return line;
}

std::string help_text(std::string_view program, Flags flags,
                      std::span<const OptionSpec> chapter_options) {
    std::string text = usage_line(program, flags, chapter_options) + "\n\n";
    if (!chapter_options.empty()) {
        text += "this chapter's own flags:\n";
        for (const auto& spec : chapter_options) {
            std::string right = spec.help, range;
            if (spec.type == OptionType::integer || spec.type == OptionType::number)
                range = format_number(spec.min) + ".." + format_number(spec.max);
            if (spec.type == OptionType::bytes)
                range = byte_count_text(uint64_t(spec.min)) + ".." +
                        byte_count_text(uint64_t(spec.max));
            // The range, unless the chapter's own words already give it.
            if (!range.empty() && right.find(range) == std::string::npos)
                right += " (" + range + ")";
            if (!spec.default_value.empty()) right += " [default: " + spec.default_value + "]";
            text += help_entry(spec.name, option_value_name(spec), right);
        }
        text += "\nshared flags:\n";
    }
    for (const SharedFlag& flag : shared_flags)
        if (takes(flags, flag.from)) text += help_entry(flag.name, flag.value, flag.help);
    return text;
}

}  // namespace vkt
