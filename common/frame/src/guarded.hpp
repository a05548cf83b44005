#pragma once
// Private to common/frame (chapter 01's exit statuses, used by every chapter):
// parsing the command line and turning a chapter's outcome into its exit
// status, shared by the harness (chapters 03 on) and the text chapters 01, 02.

#include "vkt/core/instance.hpp"
#include "vkt/frame/args.hpp"

#include <functional>
#include <span>
#include <string>

namespace vkt::detail {

// Parses the command line (--help answered here), runs check_options, then
// body: usage errors exit 2, any other exception 1 with one clear line.
int guarded(int argc, char** argv, Flags flags, std::span<const OptionSpec> chapter_options,
            const std::function<void(const Options&)>& check_options,
            const std::function<int(const Options&)>& body);

// Prints the validation layer's tally; 1 if it said anything, else 0.
int report_validation(const std::string& program, const ValidationCounts* counts);

}  // namespace vkt::detail
