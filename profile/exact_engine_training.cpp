// The run that GCC learns the exact engine's branches from, for the
// library's profile-guided build (cmake/profile_guided.cmake): the kind of
// gas the benchmarks time (area fraction 0.3), walled and periodic, in the
// caches (the linked calendar) and beyond them (the two-tier calendar and
// its look ahead), and a sparse scene searched by the particles' lines.
// Each run is short: the proportions of the engine's paths matter, not the
// counts. Its seed is none the benchmarks use (particlesim_bench's 3210,
// the scripts' 7), so that no timed scene is the one trained on. Built
// instrumented and run at build time; never installed. Exits with 1 if a
// run has no collision (a training run that teaches nothing).

#include "particlesim/engine.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/random_scene.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

namespace {

constexpr std::uint64_t training_seed = 11;

struct TrainingRun {
    std::size_t disks;
    double area_fraction;
    std::optional<particlesim::SpeedRange> speeds;  // empty: the rules' default range
    std::int64_t steps;
    particlesim::Boundary boundary;
};

std::uint64_t collisions_of(const TrainingRun& training) {
    using namespace particlesim;
    const double box = std::sqrt(static_cast<double>(training.disks) * std::numbers::pi / training.area_fraction);
    const World world{box, 1.0};
    ExactSimulation engine(world, make_random_particles(training.disks, world, {training_seed, training.speeds}),
                           ExactOptions{.boundary = training.boundary});
    run(engine, training.steps);
    return engine.totals().particle_collisions + engine.totals().wall_collisions;
}

}  // namespace

int main() {
    using particlesim::Boundary;
    const particlesim::SpeedRange gas_speeds{0.1, 1.0};
    // About 1e5 collisions each in the gas; the default scene's density
    // (1000 disks, L = 20 000) for the lines.
    const TrainingRun runs[] = {
        {10'000, 0.3, gas_speeds, 40, Boundary::walls},
        {10'000, 0.3, gas_speeds, 40, Boundary::periodic},
        {100'000, 0.3, gas_speeds, 4, Boundary::walls},
        {100'000, 0.3, gas_speeds, 4, Boundary::periodic},
        {1000, 1000 * std::numbers::pi / (20000.0 * 20000.0), std::nullopt, 300, Boundary::walls},
    };
    for (const TrainingRun& training : runs) {
        if (collisions_of(training) == 0) return 1;
    }
    return 0;
}
