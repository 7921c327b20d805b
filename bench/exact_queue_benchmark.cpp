// particlesim_bench exact_queue: where the exact engine's two-tier queue
// with the look ahead starts to beat the linked buckets. Both forced
// (ExactOptions::look_ahead) on the dense gas (area fraction 0.3, speeds 0.1
// to 1 r per step) at sizes around exact_tuning::look_ahead_from, the two
// alternating run by run, the one that goes first swapped each round, so
// that a noisy stretch of the machine falls on both. One row per size: the
// medians of the rounds, and the median and range of the per-round ratios
// (two tiers' time over the linked buckets').

#include "benchmarks.hpp"
#include "statistics.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/random_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace bench {

namespace {

using namespace particlesim;

// Seconds for `steps` steps (the construction, which makes every first
// prediction, not counted), and the collisions they had.
struct QueueRun {
    double seconds;
    std::uint64_t collisions;
};

QueueRun time_queue(const World& world, const std::vector<Particle>& particles, std::int64_t steps, bool two_tiers) {
    ExactOptions options;
    options.look_ahead = two_tiers;
    ExactSimulation exact(world, particles, options);
    const auto start = std::chrono::steady_clock::now();
    particlesim::run(exact, steps);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {seconds, exact.totals().particle_collisions + exact.totals().wall_collisions};
}

}  // namespace

void exact_queue_benchmark(bool quick) {
    std::printf("n,steps,rounds,linked_s,two_tiers_s,ratio_median,ratio_min,ratio_max,collisions\n");
    const int rounds = quick ? 1 : 7;
    const std::vector<std::size_t> sizes =
        quick ? std::vector<std::size_t>{8192, 32768}
              : std::vector<std::size_t>{8192, 12288, 16384, 20480, 24576, 28672, 32768, 49152, 65536};
    for (const std::size_t n : sizes) {
        const World world = dense_gas_world(n);
        const std::vector<Particle> particles = make_random_particles(n, world, {3210, SpeedRange{0.1, 1.0}});
        // About 5e5 collisions a run, as `particlesim_bench exact` has.
        const auto steps = static_cast<std::int64_t>(2e6 / static_cast<double>(n)) + 2;
        std::vector<double> linked, two_tiers, ratios;
        std::uint64_t collisions = 0;
        for (int round = 0; round < rounds; ++round) {
            QueueRun runs[2];
            for (const int k : {round % 2, 1 - round % 2}) runs[k] = time_queue(world, particles, steps, k == 1);
            linked.push_back(runs[0].seconds);
            two_tiers.push_back(runs[1].seconds);
            ratios.push_back(runs[1].seconds / runs[0].seconds);
            collisions = runs[1].collisions;
        }
        std::printf("%zu,%lld,%d,%.4f,%.4f,%.3f,%.3f,%.3f,%llu\n", n, static_cast<long long>(steps), rounds,
                    median(linked), median(two_tiers), median(ratios), *std::min_element(ratios.begin(), ratios.end()),
                    *std::max_element(ratios.begin(), ratios.end()), static_cast<unsigned long long>(collisions));
        std::fflush(stdout);
    }
}

}  // namespace bench
