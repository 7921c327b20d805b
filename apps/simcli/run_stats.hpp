#pragma once
// What simcli --stats reports of a run: its time, its collisions and its
// energy drift, whichever engine ran it.

#include "particlesim/engine.hpp"

#include <cstdint>

namespace simcli {

struct RunStats {
    std::int64_t steps_run = 0;  // by this process: a resumed run starts past 0
    double seconds = 0.0;
    particlesim::StepCounts totals;
    double initial_energy = 0.0;
    double final_energy = 0.0;
};

// The time and rate are this process's (a resumed run's steps since its
// checkpoint); the counts are the whole run's, over all its steps.
void print_stats(const char* engine, const RunStats& stats, std::int64_t steps);

}  // namespace simcli
