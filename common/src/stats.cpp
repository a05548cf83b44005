#include "vkt/stats.hpp"

#include <algorithm>
#include <cmath>

namespace vkt {

Summary summarize(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    const double median = n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
    const size_t rank = static_cast<size_t>(std::ceil(0.95 * double(n)));  // 1-based
    return {values.front(), median, values[std::max<size_t>(rank, 1) - 1], values.back()};
}

}  // namespace vkt
