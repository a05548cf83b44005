#pragma once
// How the soak judges growth (vk_soak.cpp), apart from the counting so that a
// unit test can feed it made-up runs (tests/unit/test_soak_growth.cpp).
//
// A sample is a snapshot of a moving process: a frame's temporaries,
// lavapipe's binning memory (which follows what the scene shows: 15's heap
// sits at 36.9 MB or at 37.6 MB for hundreds of frames at a time, 12's goes
// between 37.5 and 40.5 MB, with no trend), the heap's top page trimmed or
// not. Noise lifts some samples; a leak lifts all of them, so what is compared
// is least samples. The frames measured are cut into quarters: the first is
// warm-up still (a malloc arena reaching its size). A leak keeps growing, so
// it must show twice: in the rise from the second quarter's least sample to
// the third's, and in the rise from the third's to the last's. Each rise is
// taken per frame (the quarters are a quarter of the run apart) times the
// frames measured, and the growth is the lesser of the two: a steady leak of
// L bytes a frame reads as L times the frames, at its full size, in both.
// One step, memory kept once, shows in one rise only and reads as none. The
// CI run at d98f33e read 23's resident memory as +202 KiB with its heap flat
// (-32 bytes): 100 KiB more in the last quarter's least sample than in the
// second's, which the rule before this one (those two quarters, one rise)
// read double; 10,000 frames of 23 here stay within 4 KiB (a sample every
// 250 frames). Pages of the malloc arena touched for the first time, when
// lavapipe's threads allocate in a new order, rise like that without the
// heap in use rising; a step is not a leak. (Comparing the least sample of
// each half, as the soak first did, saw a steady leak at half its size.) A
// least-squares line through every block's least sample would use all of
// them, but read 15's long stretches at 37.6 MB as +12 to +29 KB.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>

namespace vkt::soak {

// minima[i]: the least sample of frames from + i * block .. from + (i + 1) *
// block - 1; `frames` frames measured. Returns the growth over them, in the
// samples' unit; 0 with fewer than 8 blocks (2 a quarter).
inline double quarter_growth(std::span<const int64_t> minima, uint64_t block, uint64_t frames) {
    const size_t n = minima.size(), quarter = n / 4;
    if (quarter < 2 || block == 0) return 0;
    // The least sample of blocks [first, last); the last quarter, [3q, n),
    // may hold the odd blocks, and a partial one.
    auto least = [&](size_t first, size_t last) {
        return *std::min_element(minima.begin() + std::ptrdiff_t(first),
                                 minima.begin() + std::ptrdiff_t(last));
    };
    const int64_t second = least(quarter, 2 * quarter);
    const int64_t third = least(2 * quarter, 3 * quarter);
    const int64_t fourth = least(3 * quarter, n);
    const double apart = double(quarter * block);  // frames between two quarters
    const int64_t rise = std::min(third - second, fourth - third);
    return double(rise) / apart * double(frames);
}

}  // namespace vkt::soak
