#pragma once
// How the soak judges growth (vk_soak.cpp), apart from the counting so that a
// unit test can feed it made-up runs (tests/unit/test_soak_growth.cpp).
//
// A sample is a snapshot of a moving process: a frame's temporaries,
// lavapipe's binning memory (which follows what the scene shows: 15's heap
// sits at 36.9 MB or at 37.6 MB for hundreds of frames at a time, 12's goes
// between 37.5 and 40.5 MB, with no trend), the heap's top page trimmed or
// not. Noise lifts some samples; a leak lifts all of them, so what is compared
// is least samples.
//
// The frames measured are cut into eight segments, and each segment's least
// sample is compared with the next one's: seven rises. A leak keeps growing,
// so it lifts every rise; memory kept once (a step) lifts one rise, and a
// block that comes and goes lifts one and lowers a later one. The growth is
// the median rise (the fourth of seven), taken per frame (the segments are an
// eighth of the run apart) times the frames measured: a steady leak of L
// bytes a frame reads as L times the frames, at its full size; up to three
// steps read as none.
//
// Why the median, not the least of two rises as the soak took before: 26's
// resident memory (frames 500..10,000, one run in about twenty here) took
// two unrelated steps, +60 KiB once at a random frame (a page or so of
// lavapipe's short-lived 332 KiB blocks left touched) and +1,028 KiB at frame
// 5,500 (a 1 MiB block lavapipe replaces every 2,750 frames, freeing the old
// one some hundreds of frames later), with the heap in use flat. With
// quarters, one step fell in each of the two rises and the soak read
// +242 KiB. A leak must now lift four of the seven rises: one that starts
// after about the middle of the run is missed, one that starts before it
// reads smaller than its size. A least-squares line through every block's
// least sample would use all of them, but read 15's long stretches at
// 37.6 MB as +12 to +29 KB.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace vkt::soak {

inline constexpr size_t segments = 8;

// minima[i]: the least sample of frames from + i * block .. from + (i + 1) *
// block - 1; `frames` frames measured. Returns the growth over them, in the
// samples' unit; 0 with fewer than 16 blocks (2 a segment).
inline double median_rise_growth(std::span<const int64_t> minima, uint64_t block, uint64_t frames) {
    const size_t n = minima.size(), length = n / segments;
    if (length < 2 || block == 0) return 0;
    // Segment k is blocks [k * length, (k + 1) * length); the last one also
    // takes the odd blocks, and a partial one.
    std::array<int64_t, segments> least{};
    for (size_t k = 0; k < segments; ++k) {
        const auto first = minima.begin() + std::ptrdiff_t(k * length);
        const auto last = k + 1 == segments ? minima.end() : first + std::ptrdiff_t(length);
        least[k] = *std::min_element(first, last);
    }
    std::array<int64_t, segments - 1> rises{};
    for (size_t k = 1; k < segments; ++k) rises[k - 1] = least[k] - least[k - 1];
    const auto middle = rises.begin() + rises.size() / 2;
    std::nth_element(rises.begin(), middle, rises.end());
    const double apart = double(length * block);  // frames between two segments' starts
    return double(*middle) / apart * double(frames);
}

}  // namespace vkt::soak
