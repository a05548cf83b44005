#include "vkt/core/memory_budget.hpp"

#include "vkt/core/check.hpp"

#include <cctype>
#include <charconv>

namespace vkt {

std::string byte_count_text(uint64_t bytes) {
    if (bytes >= (uint64_t(1) << 30) && bytes % (uint64_t(1) << 30) == 0)
        return std::to_string(bytes >> 30) + " GiB";
    if (bytes >= (uint64_t(1) << 20)) return std::to_string((bytes + (1 << 19)) >> 20) + " MiB";
    if (bytes >= 1024) return std::to_string((bytes + 512) >> 10) + " KiB";
    return std::to_string(bytes) + " bytes";
}

void MemoryBudget::charge(uint64_t bytes, const std::string& what) {
    // used_ <= limit_ always, so neither side overflows.
    if (bytes > limit_ - used_)
        throw Error(what + (what.empty() ? "needs " : ": needs ") + byte_count_text(bytes) +
                    ", which would bring what this file needs to " +
                    (bytes > (uint64_t(1) << 60) ? std::string("more than 2^60 bytes")
                                                 : byte_count_text(used_ + bytes)) +
                    ", past the limit of " + byte_count_text(limit_) + " (--max-memory)");
    used_ += bytes;
}

std::optional<uint64_t> parse_byte_count(std::string_view text) {
    uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end == text.data()) return std::nullopt;
    std::string unit(end, text.data() + text.size());
    for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
    int shift = 0;
    if (unit.empty() || unit == "B")
        shift = 0;
    else if (unit == "K" || unit == "KB" || unit == "KIB")
        shift = 10;
    else if (unit == "M" || unit == "MB" || unit == "MIB")
        shift = 20;
    else if (unit == "G" || unit == "GB" || unit == "GIB")
        shift = 30;
    else if (unit == "T" || unit == "TB" || unit == "TIB")
        shift = 40;
    else
        return std::nullopt;
    constexpr uint64_t most = uint64_t(1) << 50;
    if (value > (most >> shift)) return std::nullopt;
    return value << shift;
}

}  // namespace vkt
