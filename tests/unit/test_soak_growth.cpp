// The soak's judgement of growth (tests/soak/soak_growth.hpp), fed made-up
// runs shaped like the real ones: frames 500..10000, each block of 50 frames
// keeping its least sample, as tests/soak/vk_soak.cpp does.
#include "../soak/soak_growth.hpp"

#include <catch2/catch_approx.hpp>
#include <catch2/catch_test_macros.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace {

constexpr uint64_t from = 500, last = 10000, block = 50;
constexpr int64_t heap_limit = 16 * 1024;  // the soak's heap limit, bytes

// The least sample of each block, frames from..last, of heap(frame).
std::vector<int64_t> block_minima(const std::function<int64_t(uint64_t)>& heap) {
    std::vector<int64_t> minima;
    for (uint64_t frame = from; frame <= last; ++frame) {
        if ((frame - from) % block == 0) minima.push_back(heap(frame));
        minima.back() = std::min(minima.back(), heap(frame));
    }
    return minima;
}

// A frame's temporaries: some frames sample the heap while up to 200 KB of
// them are live, most do not (a fixed pseudo-random pattern).
int64_t temporaries(uint64_t frame) {
    const uint64_t hash = (frame * 2654435761u) >> 7;
    return hash % 5 == 0 ? int64_t(hash % 200'000) : 0;
}

double growth(const std::function<int64_t(uint64_t)>& heap) {
    return vkt::soak::quarter_growth(block_minima(heap), block, last - from);
}

}  // namespace

TEST_CASE("soak: a steady leak of 500 bytes a frame reads at its full size and fails", "[soak]") {
    auto leaking = [](uint64_t frame) {
        return 40'000'000 + int64_t(500 * frame) + temporaries(frame);
    };
    const double grew = growth(leaking);
    CHECK(grew == Catch::Approx(500.0 * (last - from)).epsilon(0.01));  // 4.75 MB
    CHECK(grew > heap_limit);

    // The earlier check, the least sample of each half, saw half of it.
    const std::vector<int64_t> minima = block_minima(leaking);
    const auto half = minima.begin() + std::ptrdiff_t(minima.size() / 2);
    const int64_t halves =
        *std::min_element(half, minima.end()) - *std::min_element(minima.begin(), half);
    CHECK(double(halves) == Catch::Approx(0.5 * grew).epsilon(0.02));
}

TEST_CASE("soak: a leak small enough to stay inside the limit passes", "[soak]") {
    // 1 byte a frame: 9.5 KB over the run, under 16 KiB.
    const double grew = growth([](uint64_t frame) { return 1'000'000 + int64_t(frame); });
    CHECK(grew == Catch::Approx(9500).epsilon(0.01));
    CHECK(grew < heap_limit);
}

TEST_CASE("soak: noise without a trend reads as no growth", "[soak]") {
    // Temporaries on top of a flat heap, and a heap's top page trimmed on
    // some frames only (4 KiB up and down).
    CHECK(growth([](uint64_t frame) {
              return 40'000'000 + temporaries(frame) + (frame % 7 == 0 ? 0 : 4096);
          }) == 0);
    // 15's heap: 655 KB more for stretches of 300 to 800 frames at a time,
    // as lavapipe's binning memory follows the scene.
    CHECK(growth([](uint64_t frame) {
              const uint64_t stretch = (frame / 550) * 2654435761u >> 9;
              return 36'880'000 + (stretch % 3 == 0 ? 655'000 : 0) + temporaries(frame);
          }) == 0);
}

TEST_CASE("soak: memory kept once reads as no growth, wherever in the run it is kept", "[soak]") {
    // 100 KiB kept once (the size of 23's rise in CI at d98f33e). The
    // quarters of frames 500..10000 are 2,350 frames of whole blocks each
    // (the last takes the odd ones): a step shows in one of the two rises
    // compared, never in both.
    auto step_at = [](uint64_t at) {
        return growth([at](uint64_t frame) { return frame < at ? 0 : 100 * 1024; });
    };
    for (uint64_t at : {1000u, 3000u, 5250u, 7000u, 8000u, 9500u}) {
        INFO("kept at frame " << at);
        CHECK(step_at(at) == 0);
    }
}

TEST_CASE("soak: a leak that starts mid-run, or comes in steps, still fails", "[soak]") {
    // 500 bytes a frame from frame 4000 on: both rises see it.
    const double late = growth([](uint64_t frame) {
        return 40'000'000 + (frame < 4000 ? 0 : int64_t(500 * (frame - 4000))) + temporaries(frame);
    });
    CHECK(late > heap_limit);
    // 64 KiB every 1,000 frames: a leak too, in steps.
    const double steps = growth([](uint64_t frame) { return int64_t(frame / 1000) * 65536; });
    CHECK(steps == Catch::Approx(65.536 * (last - from)).epsilon(0.15));
    CHECK(steps > heap_limit);
}

TEST_CASE("soak: too few blocks give no reading", "[soak]") {
    CHECK(vkt::soak::quarter_growth(std::vector<int64_t>{5, 6, 7, 8, 9, 10, 11}, block, 350) == 0);
}
