#include "vkt/args.hpp"

#include <charconv>
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

bool is_frame_loop_flag(std::string_view flag) {
    return flag == "--headless" || flag == "--offscreen" || flag == "--frames" ||
           flag == "--size" || flag == "--screenshot" || flag == "--benchmark";
}

}  // namespace

Options parse_args(std::span<const char* const> args, Flags flags) {
    Options options;
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
            return args[++i];
        };
        auto no_value = [&] {
            if (inline_value) throw UsageError(std::string(flag) + " takes no value");
        };

        if (flags != Flags::frame_loop && is_frame_loop_flag(flag))
            throw UsageError(std::string(flag) + " is not used by this chapter: it draws nothing");
        if (flags == Flags::instance && flag == "--device")
            throw UsageError("--device is not used by this chapter: it opens no device");

        if (flag == "--help" || flag == "-h") {
            no_value();
            options.help = true;
        } else if (flag == "--headless") {
            no_value();
            options.headless = true;
        } else if (flag == "--offscreen") {
            no_value();
            options.headless = true;  // offscreen has no window either
            options.offscreen = true;
        } else if (flag == "--benchmark") {
            no_value();
            options.benchmark = true;
        } else if (flag == "--validation") {
            no_value();
            options.validation = true;
        } else if (flag == "--no-validation") {
            no_value();
            options.validation = false;
        } else if (flag == "--frames") {
            std::string_view text = value();
            auto frames = parse_positive(text);
            if (!frames)
                throw UsageError("--frames wants a whole number of at least 1, not '" +
                                 std::string(text) + "'");
            options.frames = *frames;
        } else if (flag == "--size") {
            std::string_view text = value();
            auto x = text.find('x');
            auto w = x == std::string_view::npos ? std::nullopt : parse_positive(text.substr(0, x));
            auto h =
                x == std::string_view::npos ? std::nullopt : parse_positive(text.substr(x + 1));
            // An upper bound for any device; the runner also checks the chosen device's
            // maxImageDimension2D, which may be as small as 4096.
            constexpr uint32_t max_side = 16384;
            if (!w || !h || *w > max_side || *h > max_side)
                throw UsageError("--size wants WIDTHxHEIGHT, each 1.." + std::to_string(max_side) +
                                 ", not '" + std::string(text) + "'");
            options.width = *w;
            options.height = *h;
        } else if (flag == "--screenshot") {
            std::string_view text = value();
            if (!text.ends_with(".png") || text.size() == 4)
                throw UsageError(
                    "--screenshot writes a PNG: give a file name ending in .png, not '" +
                    std::string(text) + "'");
            options.screenshot = text;
        } else if (flag == "--device") {
            std::string_view text = value();
            if (text.empty()) throw UsageError("--device wants a name or an index");
            options.device = text;
        } else {
            throw UsageError("unknown argument '" + std::string(arg) + "'");
        }
    }
    return options;
}

std::string usage_line(std::string_view program, Flags flags) {
    std::string line = "usage: " + std::string(program);
    if (flags == Flags::frame_loop)
        line +=
            " [--headless | --offscreen] [--frames N] [--size WxH] [--screenshot FILE.png]"
            " [--benchmark]";
    if (flags != Flags::instance) line += " [--device NAME|INDEX]";
    line += " [--validation | --no-validation] [--help]";
    return line;
}

std::string help_text(std::string_view program, Flags flags) {
    std::string text = usage_line(program, flags) + "\n\n";
    if (flags == Flags::frame_loop)
        text +=
            "  --headless           no window: present to VK_EXT_headless_surface, or render\n"
            "                       offscreen where the device cannot present to it (also the\n"
            "                       choice when there is no display or no window can open)\n"
            "  --offscreen          no surface at all: render into our own images only\n"
            "  --frames N           stop after N frames; time is then frame index / 60 s\n"
            "                       (headless default: 60 frames)\n"
            "  --size WxH           size of the window or the headless image (default 800x600)\n"
            "  --screenshot FILE.png  write the last frame, as presented, as a PNG\n"
            "  --benchmark          print CPU and GPU frame times as JSON on stdout\n";
    if (flags != Flags::instance)
        text += "  --device NAME|INDEX  use this physical device (index, or part of its name)\n";
    text +=
        "  --validation         require the Khronos validation layer, with synchronisation\n"
        "                       validation; any warning or error makes the exit status 1\n"
        "  --no-validation      do not load the validation layer\n"
        "                       (default: validation on when the layer is installed)\n"
        "  --help               this text\n";
    return text;
}

}  // namespace vkt
