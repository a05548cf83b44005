// Chapter 01's promise to the reader, kept by every chapter: bad input is one
// clear line and an exit status (2 for the command line, 1 for the rest).

#include "guarded.hpp"

#include "vkt/core/memory.hpp"
#include "vkt/core/memory_budget.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace vkt::detail {

namespace {

std::string program_name(char** argv) {
    return std::filesystem::path(argv[0] ? argv[0] : "chapter").filename().string();
}

// An image too large for the device, in words: its size, and --size where
// that is what asked for it (a chapter's targets are as large as its frame),
// rather than only "vkBindImageMemory failed with ...".
std::string image_too_large(const ImageTooLarge& e, const Options& options) {
    const VkExtent2D extent = e.extent();
    const std::string size = std::to_string(extent.width) + "x" + std::to_string(extent.height);
    const std::string image =
        "an image of " + size +
        (e.samples() > 1 ? ", " + std::to_string(int(e.samples())) + " samples a pixel" : "") +
        ", needs " + byte_count_text(e.bytes()) + " (" + std::to_string(e.bytes()) + " bytes)";
    const bool frame_size = extent.width == options.width && extent.height == options.height;
    if (!e.past_limit())  // within every limit: the memory is full, or too full for it
        return (frame_size ? "--size " + size + ": " : std::string()) + image +
               ", and found no memory: " + e.what() +
               " (the device's memory is full, or too full for an image of this size)";
    if (frame_size)
        return "--size " + size + ": too large for this device: " + image + ", and " + e.what() +
               "; try a smaller --size";
    return "an image too large for this device: " + image + ", and " + e.what();
}

}  // namespace

// Turns the body's outcome into an exit status: usage errors 2, failures 1.
int guarded(int argc, char** argv, Flags flags, std::span<const OptionSpec> chapter_options,
            const std::function<void(const Options&)>& check_options,
            const std::function<int(const Options&)>& body) {
    const std::string program = program_name(argv);
    const auto usage = [&](const UsageError& e) {
        std::fprintf(stderr, "%s: %s\n%s\n", program.c_str(), e.what(),
                     usage_line(program, flags, chapter_options).c_str());
        return 2;
    };
    Options options;
    try {
        options = parse_args(std::span<const char* const>(argv + 1, size_t(std::max(argc - 1, 0))),
                             flags, chapter_options);
        if (options.help) {
            std::fputs(help_text(program, flags, chapter_options).c_str(), stdout);
            return 0;
        }
        // Flags that contradict each other, before any Vulkan object exists.
        if (check_options) check_options(options);
    } catch (const UsageError& e) {
        return usage(e);
    }
    try {
        return body(options);
    } catch (const UsageError& e) {  // a chapter may find a bad flag later, too
        return usage(e);
    } catch (const ImageTooLarge& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(),
                     image_too_large(e, options).c_str());
        return 1;
    } catch (const std::exception& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 1;
    }
}

int report_validation(const std::string& program, const ValidationCounts* counts) {
    if (!counts) return 0;
    const uint32_t warnings = counts->warnings, errors = counts->errors;
    std::fprintf(stderr, "%s: validation: %u warnings, %u errors\n", program.c_str(), warnings,
                 errors);
    return warnings + errors > 0 ? 1 : 0;
}

}  // namespace vkt::detail
