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
// warm-up still (a malloc arena reaching its size), and the growth is the rise
// from the least sample of the second quarter to the least of the last, per
// frame (they are half the run apart), times the frames measured. A steady
// leak of L bytes a frame reads as L times the frames, at its full size.
// (Comparing the least sample of each half, as the soak first did, saw a
// steady leak at half its size: the least of the second half is its first
// frames.) A single step reads double in the third quarter, not at all in the
// first. A least-squares line through every block's least sample would use
// all of them, but read 15's long stretches at 37.6 MB as +12 to +29 KB.

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
    // The second quarter, blocks [q, 2q); the last, [3q, n) (it may hold the
    // odd blocks, and a partial one).
    const int64_t second = *std::min_element(minima.begin() + std::ptrdiff_t(quarter),
                                             minima.begin() + std::ptrdiff_t(2 * quarter));
    const int64_t last =
        *std::min_element(minima.begin() + std::ptrdiff_t(3 * quarter), minima.end());
    const double apart = double(2 * quarter * block);  // frames between the two quarters
    return double(last - second) / apart * double(frames);
}

}  // namespace vkt::soak
