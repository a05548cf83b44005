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
//   build/release/bin/physics_bench --stacks [--substeps N] [--iterations N] [--hertz H]
//           [--stiff-substeps N] [--stiff-iterations N] [--stiff-height N] [--stiff-ratio R]
//       Stacks that statics say must stand or fall, stepped awake with the
//       solver's settings as given (the chapter's by default): the 20-box
//       staircase at 63%, 80%, 93% and 110% of its tipping lean, ten boxes
//       100 times heavier on a light one, one box 1,000 times heavier on a
//       light one; then the default run's colliding median with the same
//       settings, so that what a setting holds and what it costs come from
//       one run. The solver options apply to the default run too;
//       --stiff-substeps 0 turns the per-island stiff sub-steps off.
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

int scene(uint32_t count, uint32_t seed, const SolverSettings& solver) {
    Settings settings;
    settings.solver = solver;
    World world(settings);
    add_falling_boxes(world, count, seed);
    const int steps_per_second = 120;
    const int first = 3 * steps_per_second / 2, last = 9 * steps_per_second / 2;
    Run colliding;
    std::size_t manifolds = 0, points = 0, awake = 0, stiff = 0;
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
        stiff += world.stiff_count();
    }
    const double n = double(last - first), total = colliding.sum.total();
    std::printf(
        "{\"boxes\": %u, \"phase\": \"colliding\", \"from_s\": 1.5, \"to_s\": 4.5, "
        "\"median_ms\": %.3f, \"median_cpu_ms\": %.3f, \"broad\": %.3f, \"narrow\": %.3f, "
        "\"solver\": %.3f, \"other\": %.3f, \"mean_awake\": %.0f, \"mean_manifolds\": %.0f, "
        "\"mean_points\": %.0f, \"mean_stiff\": %.0f}\n",
        count, median(colliding.wall), median(colliding.cpu), colliding.sum.broad / total,
        colliding.sum.narrow / total, colliding.sum.solver / total, colliding.sum.other / total,
        double(awake) / n, double(manifolds) / n, double(points) / n, double(stiff) / n);
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

// [stacks]
// The probes of --stacks: worlds on a static floor (top face at y = 0),
// never asleep, so that only the solver holds them.
World awake_floor_world(const SolverSettings& solver) {
    Settings settings;
    settings.solver = solver;
    settings.sleep.enabled = false;
    World world(settings);
    world.add_box({0, -0.5f, 0}, {20, 0.5f, 20}, 0.0f);
    return world;
}

// Chapter 14's tower boxes (0.6 x 0.5 x 0.6 m), 20 of them, box k standing
// lean k further along x. By statics the 19 boxes above the lowest have
// their centre beyond its edge when lean > 0.030 m (10 lean > 0.3 m).
void staircase(const SolverSettings& solver, float of_tipping) {
    constexpr float kTipping = 0.030f;
    const float lean = of_tipping * kTipping;
    World world = awake_floor_world(solver);
    for (int k = 0; k < 20; ++k)
        world.add_box({lean * float(k), 0.25f + 0.5f * float(k), 0}, {0.3f, 0.25f, 0.3f}, 500.0f);
    const std::size_t top = 20;
    // 40 s: fallen once the top box is 1.75 m below where it was put; where
    // the top settles is taken at 10 s, and its sway is how far it strays
    // from there in the 30 s after.
    double fell_at = -1.0, settled = 0.0, sway = 0.0;
    const double begin = cpu_ms();  // the stacks' own cost: CPU per step, while it stands
    double standing_ms = 0.0;
    int standing_steps = 0;
    for (int i = 1; i <= 120 * 40; ++i) {
        world.step();
        if (fell_at < 0.0) standing_ms = cpu_ms() - begin, standing_steps = i;
        const glm::vec3 p = world.bodies()[top].position;
        if (fell_at < 0.0 && p.y < 8.0f) fell_at = double(i) / 120.0;
        if (i == 120 * 10) settled = p.x;
        if (i > 120 * 10) sway = std::max(sway, std::abs(double(p.x) - settled));
    }
    std::printf(
        "{\"probe\": \"staircase\", \"of_tipping\": %.2f, \"lean_m\": %.4f, "
        "\"fell_at_s\": %.2f, \"top_x_at_10s_m\": %.4f, \"sway_10_40s_mm\": %.1f, "
        "\"standing_step_us\": %.1f}\n",
        of_tipping, lean, fell_at, fell_at < 0.0 ? settled : -1.0,
        fell_at < 0.0 ? sway * 1000.0 : -1.0, 1000.0 * standing_ms / standing_steps);
    std::fflush(stdout);
}

// `count` cubes of 0.6 m, each `ratio` times as dense as the one cube under
// them, 60 s awake: when the top cube first strays 0.1 m from where it was
// put (fallen), the fastest twist about the vertical of any cube, and how far
// the top has sunk after 2 s and after 60 s (the springs' give under the load).
void heavy_on_light(const SolverSettings& solver, float ratio, int count) {
    World world = awake_floor_world(solver);
    world.add_box({0, 0.3f, 0}, glm::vec3(0.3f), 500.0f);
    for (int k = 0; k < count; ++k)
        world.add_box({0, 0.9f + 0.6f * float(k), 0}, glm::vec3(0.3f), 500.0f * ratio);
    const std::size_t top = std::size_t(count) + 1;
    const glm::vec3 put = world.bodies()[top].position;
    double fell_at = -1.0, twist = 0.0, sunk = 0.0;
    for (int i = 1; i <= 120 * 60; ++i) {
        world.step();
        const glm::vec3 p = world.bodies()[top].position;
        if (fell_at < 0.0 && glm::length(p - put) > 0.1f) fell_at = double(i) / 120.0;
        if (i == 240) sunk = double(put.y - p.y);
        for (const Body& body : world.bodies())
            twist = std::max(twist, double(std::abs(body.angular_velocity.y)));
    }
    const double sunk_at_end = double(put.y - world.bodies()[top].position.y);
    std::printf(
        "{\"probe\": \"heavy_on_light\", \"ratio\": %.0f, \"heavy_boxes\": %d, "
        "\"fell_at_s\": %.2f, \"sunk_at_2s_mm\": %.2f, \"sunk_at_60s_mm\": %.2f, "
        "\"most_twist_rad_s\": %.4f}\n",
        ratio, count, fell_at, sunk * 1000.0, fell_at < 0.0 ? sunk_at_end * 1000.0 : -1.0, twist);
    std::fflush(stdout);
}

int stacks(const SolverSettings& solver) {
    std::printf(
        "{\"probe\": \"settings\", \"substeps\": %d, \"iterations\": %d, "
        "\"relax_iterations\": %d, \"contact_hertz\": %.1f, \"stiff_substeps\": %d, "
        "\"stiff_iterations\": %d, \"stiff_height\": %d, \"stiff_mass_ratio\": %.0f}\n",
        solver.substeps, solver.iterations, solver.relax_iterations, double(solver.contact_hertz),
        solver.stiff_substeps, solver.stiff_iterations, solver.stiff_height,
        double(solver.stiff_mass_ratio));
    for (float of_tipping : {0.63f, 0.80f, 0.93f, 1.10f}) staircase(solver, of_tipping);
    heavy_on_light(solver, 100.0f, 10);
    heavy_on_light(solver, 1000.0f, 1);
    return scene(1000, 14, solver);
}
// [/stacks]

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

// A whole number from `low` to `high` for option `name`, or false with a message.
bool parse_int(const char* name, const char* text, long low, long high, int& out) {
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < low || value > high) {
        std::fprintf(stderr, "physics_bench: %s is from %ld to %ld, not '%s'\n", name, low, high,
                     text);
        return false;
    }
    out = int(value);
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
    bool probe_stacks = false;
    SolverSettings solver;
    for (int i = 1; i < argc; i += 2) {
        const bool has_value = i + 1 < argc;
        if (std::strcmp(argv[i], "--stacks") == 0) {
            probe_stacks = true;
            --i;  // no value
        } else if (has_value && std::strcmp(argv[i], "--count") == 0) {
            if (!parse_count(argv[i + 1], count)) return 2;
        } else if (has_value && std::strcmp(argv[i], "--substeps") == 0) {
            if (!parse_int("--substeps", argv[i + 1], 1, 64, solver.substeps)) return 2;
        } else if (has_value && std::strcmp(argv[i], "--iterations") == 0) {
            if (!parse_int("--iterations", argv[i + 1], 1, 64, solver.iterations)) return 2;
        } else if (has_value && std::strcmp(argv[i], "--stiff-substeps") == 0) {
            if (!parse_int("--stiff-substeps", argv[i + 1], 0, 64, solver.stiff_substeps)) return 2;
        } else if (has_value && std::strcmp(argv[i], "--stiff-iterations") == 0) {
            if (!parse_int("--stiff-iterations", argv[i + 1], 1, 64, solver.stiff_iterations))
                return 2;
        } else if (has_value && std::strcmp(argv[i], "--stiff-height") == 0) {
            if (!parse_int("--stiff-height", argv[i + 1], 1, 65536, solver.stiff_height)) return 2;
        } else if (has_value && std::strcmp(argv[i], "--stiff-ratio") == 0) {
            int ratio = 0;
            if (!parse_int("--stiff-ratio", argv[i + 1], 1, 1000000, ratio)) return 2;
            solver.stiff_mass_ratio = float(ratio);
        } else if (has_value && std::strcmp(argv[i], "--hertz") == 0) {
            int hertz = 0;
            if (!parse_int("--hertz", argv[i + 1], 1, 100000, hertz)) return 2;
            solver.contact_hertz = float(hertz);
        } else if (has_value && std::strcmp(argv[i], "--seed") == 0) {
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
                         "usage: physics_bench [--stacks] [--count N] [--seed S] [--substeps N] "
                         "[--iterations N] [--hertz H] [--stiff-substeps N] "
                         "[--stiff-iterations N] [--stiff-height N] [--stiff-ratio R] | --scaling "
                         "[COUNT...]\n");
            return 2;
        }
    }
    return probe_stacks ? stacks(solver) : scene(count, seed, solver);
}
