// physics_bench: the time of one physics step (vkt/domains/physics.hpp, chapter 14).
// Not a test: it prints JSON lines.
//
//   build/release/bin/physics_bench [--count N] [--seed S]
//       Chapter 14's scene (vkt::physics::add_falling_boxes, N = 1000 boxes,
//       its boxes' sizes and turns drawn from seed S, 14 by default):
//       the median step while the boxes collide (the steps from 1.5 s to 4.5 s
//       of simulated time, when the ten levels land on one another and
//       tumble), with the shares of the broad phase, the narrow phase and the
//       solver; then, once every box is asleep, the median of 240 more steps.
//   build/release/bin/physics_bench --scaling [COUNT...]
//       For each count (default 250 500 ... 16000): the scene after 2 s, then
//       the same world stepped with each broad phase, brute force and
//       sort-and-sweep, and each broad phase alone (CPU times).
//
// Times: each step's wall-clock time and the thread's CPU time (which a
// machine busy with other work inflates less); medians of each.
#include "vkt/domains/physics_scene.hpp"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

using namespace vkt::physics;

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double wall_ms() {
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Times of a run of steps: wall and CPU per step, and the world's own split.
struct Run {
    std::vector<double> wall, cpu;
    StepTimes sum;
    void step(World& world) {
        const double w0 = wall_ms(), c0 = cpu_ms();
        world.step();
        cpu.push_back(cpu_ms() - c0);
        wall.push_back(wall_ms() - w0);
        const StepTimes& t = world.times();
        sum.broad += t.broad, sum.narrow += t.narrow, sum.solver += t.solver, sum.other += t.other;
    }
};

int scene(uint32_t count, uint32_t seed) {
    World world;
    add_falling_boxes(world, count, seed);
    const int steps_per_second = 120;
    const int first = 3 * steps_per_second / 2, last = 9 * steps_per_second / 2;
    Run colliding;
    std::size_t manifolds = 0, points = 0, awake = 0;
    int step = 0;
    for (; step < last; ++step) {
        if (step < first) {
            world.step();
            continue;
        }
        colliding.step(world);
        manifolds += world.manifolds().size();
        points += world.contact_points();
        awake += world.awake_count();
    }
    const double n = double(last - first), total = colliding.sum.total();
    std::printf(
        "{\"boxes\": %u, \"phase\": \"colliding\", \"from_s\": 1.5, \"to_s\": 4.5, "
        "\"median_ms\": %.3f, \"median_cpu_ms\": %.3f, \"broad\": %.3f, \"narrow\": %.3f, "
        "\"solver\": %.3f, \"other\": %.3f, \"mean_awake\": %.0f, \"mean_manifolds\": %.0f, "
        "\"mean_points\": %.0f}\n",
        count, median(colliding.wall), median(colliding.cpu), colliding.sum.broad / total,
        colliding.sum.narrow / total, colliding.sum.solver / total, colliding.sum.other / total,
        double(awake) / n, double(manifolds) / n, double(points) / n);
    std::fflush(stdout);
    // On until every box sleeps (a minute at most), then 240 steps asleep.
    for (; world.awake_count() > 0 && step < 60 * steps_per_second; ++step) world.step();
    if (world.awake_count() > 0) {
        std::fprintf(stderr, "physics_bench: %zu boxes still awake after 60 s\n",
                     world.awake_count());
        return 1;
    }
    const double asleep_at = double(step) / steps_per_second;
    Run asleep;
    for (int i = 0; i < 240; ++i) asleep.step(world);
    std::printf(
        "{\"boxes\": %u, \"phase\": \"asleep\", \"asleep_at_s\": %.2f, \"median_ms\": %.3f, "
        "\"median_cpu_ms\": %.3f, \"broad\": %.3f, \"narrow\": %.3f, \"solver\": %.3f, "
        "\"other\": %.3f}\n",
        count, asleep_at, median(asleep.wall), median(asleep.cpu),
        asleep.sum.broad / asleep.sum.total(), asleep.sum.narrow / asleep.sum.total(),
        asleep.sum.solver / asleep.sum.total(), asleep.sum.other / asleep.sum.total());
    return 0;
}

// Median CPU milliseconds per step over `steps` steps of a copy of `world`.
double time_steps(World world, BroadPhase broad_phase, int steps) {
    world.settings().broad_phase = broad_phase;
    std::vector<double> ms;
    for (int i = 0; i < steps; ++i) {
        const double begin = cpu_ms();
        world.step();
        ms.push_back(cpu_ms() - begin);
    }
    return median(ms);
}

// Median CPU milliseconds of the broad phase alone (its AABBs given), on the same world.
double time_pairs(const World& world, BroadPhase broad_phase, int runs) {
    std::vector<Aabb> aabbs;
    for (const Body& b : world.bodies())
        aabbs.push_back(world_aabb(b.position, rotation(b), b.half_extents, 0.005f));
    SweepAndPrune sweep;
    std::vector<Pair> pairs;
    std::vector<double> ms;
    std::size_t found = 0;
    for (int i = 0; i < runs; ++i) {
        const double begin = cpu_ms();
        if (broad_phase == BroadPhase::brute_force)
            find_pairs_brute_force(aabbs, world.bodies(), pairs);
        else
            sweep.find_pairs(aabbs, world.bodies(), pairs);
        ms.push_back(cpu_ms() - begin);
        found += pairs.size();
    }
    if (found == 0) std::fprintf(stderr, "physics_bench: no pairs?\n");
    return median(ms);
}

int scaling(std::vector<uint32_t> counts) {
    if (counts.empty()) counts = {250, 500, 1000, 2000, 4000, 8000, 16000};
    for (uint32_t count : counts) {
        World world;
        add_falling_boxes(world, count);
        for (int i = 0; i < 240; ++i) world.step();  // 2 s: landing, in contact
        const std::size_t manifolds = world.manifolds().size();
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
            count, manifolds, brute, sweep, brute_pairs, sweep_pairs);
        std::fflush(stdout);
    }
    return 0;
}

bool parse_count(const char* text, uint32_t& count) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 1 || value > 65536) {
        std::fprintf(stderr, "physics_bench: a count is from 1 to 65536, not '%s'\n", text);
        return false;
    }
    count = uint32_t(value);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::strcmp(argv[1], "--scaling") == 0) {
        std::vector<uint32_t> counts;
        for (int i = 2; i < argc; ++i)
            if (!parse_count(argv[i], counts.emplace_back())) return 2;
        return scaling(counts);
    }
    uint32_t count = 1000, seed = 14;
    for (int i = 1; i < argc; i += 2) {
        if (i + 1 < argc && std::strcmp(argv[i], "--count") == 0) {
            if (!parse_count(argv[i + 1], count)) return 2;
        } else if (i + 1 < argc && std::strcmp(argv[i], "--seed") == 0) {
            char* end = nullptr;
            const unsigned long value = std::strtoul(argv[i + 1], &end, 10);
            if (end == argv[i + 1] || *end != '\0' || value > 0xffffffffUL) {
                std::fprintf(stderr, "physics_bench: a seed is a whole number, not '%s'\n",
                             argv[i + 1]);
                return 2;
            }
            seed = uint32_t(value);
        } else {
            std::fprintf(stderr,
                         "usage: physics_bench [--count N] [--seed S] | --scaling [COUNT...]\n");
            return 2;
        }
    }
    return scene(count, seed);
}
