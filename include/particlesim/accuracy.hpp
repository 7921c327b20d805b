#pragma once
// How far the step rules are from real hard disks on a given scene: the
// stepped engine (with its substeps) measured against the exact engine on the
// same start. Record each run once, then compare records.

#include "particlesim/exact_simulation.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/sim_params.hpp"
#include "particlesim/simulation.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

// What a run did, as the metrics need it.
struct RunRecord {
    std::int64_t steps = 0;
    std::size_t particle_count = 0;
    std::uint64_t particle_collisions = 0;
    std::uint64_t wall_collisions = 0;
    std::uint64_t overlapping_particle_steps = 0;  // particles overlapping another, summed over the steps
    std::vector<Vec2> positions_after_1;           // empty when the run is shorter
    std::vector<Vec2> positions_after_10;
    double largest_energy_drift = 0.0;  // max over steps of |E - E0| / E0, at full precision
    double seconds = 0.0;               // in the engine's steps only, not in the measuring
};

// Runs `steps` steps of the engine and records them.
RunRecord record_run(Simulation& engine, std::int64_t steps);
RunRecord record_run(ExactSimulation& engine, std::int64_t steps);

struct AccuracyReport {
    double particle_collision_rate_error = 0.0;  // (stepped - exact) / exact; 0 when both are 0
    double wall_collision_rate_error = 0.0;      // the same for walls: the pressure on the walls
    double overlap_fraction = 0.0;               // of the stepped run's particle-steps
    double position_error_1 = 0.0;               // RMS distance to the exact positions after 1 step, over L
    double position_error_10 = 0.0;              // the same after 10 steps (before chaos dominates)
    double energy_drift = 0.0;                   // the stepped run's largest relative drift
};

AccuracyReport compare_to_exact(const RunRecord& stepped, const RunRecord& exact, const SimParams& params);

// Both runs from the same start, then the comparison. Throws OverlappingStart
// when the start has overlaps (the exact engine has no ground truth then).
AccuracyReport measure_accuracy(const SimParams& params, const std::vector<Particle>& particles,
                                const SimOptions& stepped_options, std::int64_t steps);

}  // namespace particlesim
