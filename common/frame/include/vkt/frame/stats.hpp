#pragma once
// Summaries of frame times for --benchmark, taught in chapter 03 (the runner's
// frame and GPU times); chapter 15 also summarises its own CPU record times.

#include <string>
#include <string_view>
#include <vector>

namespace vkt {

struct Summary {
    double min = 0, median = 0, p95 = 0, max = 0;
};

// Median: the middle value (mean of the two middle ones for an even count).
// p95: the nearest-rank 95th percentile, the smallest value that is at least
// as large as 95% of all values. An empty input gives all zeros.
Summary summarize(std::vector<double> values);

// {"min": 1.0000, "median": 2.5000, "p95": 4.0000, "max": 4.0000}, or null for
// no values: how --benchmark prints a summary.
std::string json_summary(const std::vector<double>& values);

// A JSON string literal: quotes, with backslashes, quotes and control
// characters escaped.
std::string json_string(std::string_view text);

}  // namespace vkt
