// physics_bench: the time of one physics step (vkt/domains/physics.hpp, chapter 14)
// against the number of boxes, with the brute-force broad phase and with
// sort-and-sweep. Not a test: it prints one JSON line per box count.
//
//   build/release/bin/physics_bench [COUNT...]   (default 250 500 ... 16000)
//
// Each count: chapter 14's scene (vkt::physics::add_falling_boxes), 2 s
// simulated with sort-and-sweep so the boxes have landed and touch, then the
// same world stepped with each broad phase; medians of the step times.
#include "vkt/domains/physics.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using namespace vkt::physics;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Median milliseconds per step over `steps` steps of a copy of `world`.
double time_steps(World world, BroadPhase broad_phase, int steps) {
    world.settings().broad_phase = broad_phase;
    std::vector<double> ms;
    for (int i = 0; i < steps; ++i) {
        const auto begin = std::chrono::steady_clock::now();
        world.step();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
                .count());
    }
    return median(ms);
}

// Median milliseconds of the broad phase alone, on the same world.
double time_pairs(const World& world, BroadPhase broad_phase, int runs) {
    std::vector<uint32_t> order;
    std::vector<double> ms;
    std::size_t found = 0;
    for (int i = 0; i < runs; ++i) {
        const auto begin = std::chrono::steady_clock::now();
        found += broad_phase == BroadPhase::brute_force
                     ? find_pairs_brute_force(world.bodies()).size()
                     : find_pairs_sweep(world.bodies(), order).size();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
                .count());
    }
    if (found == 0) std::fprintf(stderr, "physics_bench: no pairs?\n");
    return median(ms);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<uint32_t> counts = {250, 500, 1000, 2000, 4000, 8000, 16000};
    if (argc > 1) {
        counts.clear();
        for (int i = 1; i < argc; ++i) {
            const long value = std::strtol(argv[i], nullptr, 10);
            if (value < 1 || value > 65536) {
                std::fprintf(stderr, "physics_bench: a count is from 1 to 65536, not '%s'\n",
                             argv[i]);
                return 2;
            }
            counts.push_back(uint32_t(value));
        }
    }
    for (uint32_t count : counts) {
        World world;
        add_falling_boxes(world, count);
        for (int i = 0; i < 240; ++i) world.step();  // 2 s: landed, in contact
        const std::size_t contacts = world.contact_count();
        // Fewer brute-force steps where each is slow: n^2 / 2 tests.
        const int brute_steps = count <= 2000 ? 31 : count <= 8000 ? 11 : 5;
        const double brute = time_steps(world, BroadPhase::brute_force, brute_steps);
        const double sweep = time_steps(world, BroadPhase::sweep_and_prune, 31);
        const double brute_pairs = time_pairs(world, BroadPhase::brute_force, brute_steps);
        const double sweep_pairs = time_pairs(world, BroadPhase::sweep_and_prune, 31);
        std::printf(
            "{\"boxes\": %u, \"contacts\": %zu, \"step_brute_force_ms\": %.4f, "
            "\"step_sweep_ms\": %.4f, \"pairs_brute_force_ms\": %.4f, "
            "\"pairs_sweep_ms\": %.4f}\n",
            count, contacts, brute, sweep, brute_pairs, sweep_pairs);
        std::fflush(stdout);
    }
    return 0;
}
