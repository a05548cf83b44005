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
// The frames measured are cut into eight segments. The first is warm-up
// still (a malloc arena reaching its size); from the second on, each
// segment's least sample is compared with the next one's: six rises. A leak
// keeps growing, so it lifts every rise; memory kept once (a step) lifts one,
// and memory that grows for a while and is then given back (28's heap goes
// up and down by a megabyte as its scene moves) lowers one. The growth is the
// least of the six rises, taken per frame (the segments are an eighth of the
// run apart) times the frames measured: a steady leak of L bytes a frame
// reads as L times the frames, at its full size; up to five steps read as
// none. A leak must be there by the start of the third eighth: one that
// starts later leaves the first rise flat, and reads as none.
//
// Why six rises, not two as the soak took before (the least of the rises
// from the second quarter to the third and from the third to the last):
// 26's resident memory (frames 500..10,000, one run in about twenty here)
// took two unrelated steps with the heap in use flat, +60 KiB once at a
// random frame (pages of lavapipe's short-lived 332 KiB blocks left touched)
// and +1,028 KiB at frame 5,500 (a 1 MiB block lavapipe replaces every 2,750
// frames, freeing the old one some hundreds of frames later). One step fell
// in each of the two rises and the soak read +242 KiB. (The median of the
// rises would ignore steps but not a slow climb with one fall: it read 28's
// heap as +542 KB in every run.) A least-squares line through every block's
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
inline double least_rise_growth(std::span<const int64_t> minima, uint64_t block, uint64_t frames) {
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
    int64_t rise = least[2] - least[1];  // segment 0 is warm-up
    for (size_t k = 3; k < segments; ++k) rise = std::min(rise, least[k] - least[k - 1]);
    const double apart = double(length * block);  // frames between two segments' starts
    return double(rise) / apart * double(frames);
}

}  // namespace vkt::soak
