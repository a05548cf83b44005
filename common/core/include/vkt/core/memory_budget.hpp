#pragma once
// How much memory a file may make a chapter spend: chapters 09 and 10 (an
// image, a glTF model), whose files may come from anywhere. A file of a few
// bytes can claim gigabytes (a PNG header, an accessor's count, a base64
// data: URI), and a chapter that believed it would freeze a reader's laptop
// before any error could be printed. So every large allocation a file asks
// for is charged here first, from what the file says, and refused by name
// with the numbers when the total would pass the limit (--max-memory).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vkt {

// --max-memory's default: 1 GiB. A chapter's peak is its budget plus what
// Vulkan itself takes (about 110 MiB on lavapipe with validation), so 1 GiB
// leaves an 8 GB laptop its desktop, a browser and the book while a chapter
// loads what it allows, 8192 x 8192 textures among them (939 MiB). Measured
// (tests/hostile_peaks.py, README's table): with 2 GiB, a PNG of 11,500 x
// 11,500 in 408 KiB took 09_textures to 1.8 GB. Every asset of this
// repository needs less than 16 MiB.
inline constexpr uint64_t default_max_memory = uint64_t(1) << 30;

class MemoryBudget {
public:
    explicit MemoryBudget(uint64_t limit = default_max_memory) : limit_(limit) {}

    // Counts `bytes` that `what` is about to allocate. Past the limit it
    // throws Error "WHAT: needs N MiB, which would bring what this file
    // needs to T MiB, past the limit of L MiB (--max-memory)" (an empty
    // `what`: the message begins "needs"). What is
    // charged stays charged: the budget counts every large allocation a
    // load makes, freed or not, so it holds the peak whatever the order.
    void charge(uint64_t bytes, const std::string& what);

    uint64_t used() const { return used_; }
    uint64_t limit() const { return limit_; }

private:
    uint64_t limit_;
    uint64_t used_ = 0;
};

// Bytes as the messages print them: "2 GiB" (whole GiB), "37 MiB", "512 KiB", "100 bytes".
std::string byte_count_text(uint64_t bytes);

// A size as a reader types it: a whole number of bytes, or with the suffix
// K, M, G or T (powers of 1024; "KiB", "MB" and lower case too): "512M",
// "2G", "1536MiB". nullopt where it is not one, or is past 2^50.
std::optional<uint64_t> parse_byte_count(std::string_view text);

}  // namespace vkt
