#include "vkt/frame/stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vkt {

Summary summarize(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    const double median = n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
    const size_t rank = static_cast<size_t>(std::ceil(0.95 * double(n)));  // 1-based
    return {values.front(), median, values[std::max<size_t>(rank, 1) - 1], values.back()};
}

std::string json_summary(const std::vector<double>& values) {
    if (values.empty()) return "null";
    const Summary s = summarize(values);
    char text[160];
    std::snprintf(text, sizeof text, R"({"min": %.4f, "median": %.4f, "p95": %.4f, "max": %.4f})",
                  s.min, s.median, s.p95, s.max);
    return text;
}

std::string json_string(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

}  // namespace vkt
