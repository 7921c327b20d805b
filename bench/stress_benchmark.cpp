// The long stability run (the quick ones are in tests/test_stability.cpp): a
// crowded box for 1e6 steps under both engines, every step checked for NaN
// and escape, the energy drift measured at full precision after every step.

#include "benchmarks.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "stress_scenes.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace particlesim;

namespace bench {

namespace {

template <typename Engine>
void stress_row(const char* engine_name, Engine& engine, const World& params, std::int64_t steps) {
    const auto start = std::chrono::steady_clock::now();
    const double drift = stress_scenes::run_checked(engine, params, steps);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const bool valid = std::isfinite(drift);
    std::printf("crowded box,%zu,%g,%lld,%s,%s,%.3g,%s,%llu,%llu,%.1f\n", engine.particles().size(), params.box_size,
                static_cast<long long>(steps), engine_name, valid ? "yes" : "NO", drift, drift <= 1e-12 ? "yes" : "NO",
                static_cast<unsigned long long>(engine.totals().particle_collisions),
                static_cast<unsigned long long>(engine.totals().wall_collisions), seconds);
    std::fflush(stdout);
}

}  // namespace

void stress_benchmark(bool quick) {
    std::printf(
        "scene,n,box_size,steps,engine,every_step_valid,largest_energy_drift,drift_within_1e-12,"
        "particle_collisions,wall_collisions,seconds\n");
    const std::int64_t steps = quick ? 20000 : 1000000;
    const NamedScene scene = stress_scenes::crowded_box();
    for (const int threads : {1, 2}) {
        SteppedSimulation stepped(scene.world, scene.particles, {.threads = threads});
        stress_row(threads == 1 ? "step (1 thread)" : "step (2 threads)", stepped, scene.world, steps);
    }
    SteppedSimulation substeps(scene.world, scene.particles, {.threads = 1, .substeps = 4});
    stress_row("step K=4", substeps, scene.world, steps / 4);
    ExactSimulation exact(scene.world, scene.particles);
    stress_row("exact", exact, scene.world, steps);
}

}  // namespace bench
