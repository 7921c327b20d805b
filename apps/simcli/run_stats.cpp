#include "run_stats.hpp"

#include "particlesim/accuracy.hpp"

#include <cstdio>

namespace simcli {

void print_stats(const char* engine, const RunStats& stats, std::int64_t steps) {
    const double per_step = steps > 0 ? 1.0 / static_cast<double>(steps) : 0.0;
    std::fprintf(stderr, "stats: engine %s, %lld steps in %.6f s (%.6g steps/s)\n", engine,
                 static_cast<long long>(stats.steps_run), stats.seconds,
                 stats.seconds > 0.0 ? static_cast<double>(stats.steps_run) / stats.seconds : 0.0);
    std::fprintf(stderr, "stats: %llu particle collisions, %llu wall collisions\n",
                 static_cast<unsigned long long>(stats.totals.particle_collisions),
                 static_cast<unsigned long long>(stats.totals.wall_collisions));
    std::fprintf(stderr, "stats: relative energy drift %+.16e\n",
                 particlesim::relative_energy_drift(stats.initial_energy, stats.final_energy));
    std::fprintf(stderr, "stats: %.6g candidate pairs tested per step\n",
                 static_cast<double>(stats.totals.pair_tests) * per_step);
}

}  // namespace simcli
