#pragma once
// Summaries of frame times for --benchmark.

#include <vector>

namespace vkt {

struct Summary {
    double min = 0, median = 0, p95 = 0, max = 0;
};

// Median: the middle value (mean of the two middle ones for an even count).
// p95: the nearest-rank 95th percentile, the smallest value that is at least
// as large as 95% of all values. An empty input gives all zeros.
Summary summarize(std::vector<double> values);

}  // namespace vkt
