#include "particlesim/accuracy.hpp"

#include "particlesim/energy.hpp"
#include "particlesim/overlap_counter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace particlesim {

namespace {

std::vector<Vec2> positions_of(std::span<const Particle> particles) {
    std::vector<Vec2> positions;
    positions.reserve(particles.size());
    for (const Particle& p : particles) positions.push_back(p.position);
    return positions;
}

template <typename Engine>
RunRecord record(Engine& engine, const SimParams& params, std::int64_t steps) {
    RunRecord run;
    run.steps = steps;
    run.particle_count = engine.particles().size();
    OverlapCounter overlaps;
    const double initial_energy = total_kinetic_energy(engine.particles());
    for (std::int64_t s = 1; s <= steps; ++s) {
        const auto start = std::chrono::steady_clock::now();
        engine.step();
        run.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::span<const Particle> particles = engine.particles();
        run.particle_collisions += engine.last_step().particle_collisions;
        run.wall_collisions += engine.last_step().wall_collisions;
        run.overlapping_particle_steps += overlaps.count(particles, params);
        const double drift = std::abs(relative_energy_drift(initial_energy, total_kinetic_energy(particles)));
        run.largest_energy_drift = std::max(run.largest_energy_drift, drift);
        if (s == 1) run.positions_after_1 = positions_of(particles);
        if (s == 10) run.positions_after_10 = positions_of(particles);
    }
    return run;
}

double relative_error(std::uint64_t measured, std::uint64_t truth) {
    if (truth == 0) return measured == 0 ? 0.0 : std::numeric_limits<double>::infinity();
    return (static_cast<double>(measured) - static_cast<double>(truth)) / static_cast<double>(truth);
}

double rms_distance_over_box(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double box_size) {
    if (a.empty() || a.size() != b.size()) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
    return std::sqrt(sum / static_cast<double>(a.size())) / box_size;
}

}  // namespace

RunRecord record_run(Simulation& engine, std::int64_t steps) { return record(engine, engine.params(), steps); }
RunRecord record_run(ExactSimulation& engine, std::int64_t steps) { return record(engine, engine.params(), steps); }

AccuracyReport compare_to_exact(const RunRecord& stepped, const RunRecord& exact, const SimParams& params) {
    if (stepped.steps != exact.steps) throw std::invalid_argument("compare_to_exact: the runs have different lengths");
    AccuracyReport report;
    report.particle_collision_rate_error = relative_error(stepped.particle_collisions, exact.particle_collisions);
    report.wall_collision_rate_error = relative_error(stepped.wall_collisions, exact.wall_collisions);
    const double particle_steps = static_cast<double>(stepped.particle_count) * static_cast<double>(stepped.steps);
    report.overlap_fraction = particle_steps > 0.0 ? static_cast<double>(stepped.overlapping_particle_steps) / particle_steps : 0.0;
    report.position_error_1 = rms_distance_over_box(stepped.positions_after_1, exact.positions_after_1, params.box_size);
    report.position_error_10 = rms_distance_over_box(stepped.positions_after_10, exact.positions_after_10, params.box_size);
    report.energy_drift = stepped.largest_energy_drift;
    return report;
}

AccuracyReport measure_accuracy(const SimParams& params, const std::vector<Particle>& particles,
                                const SimOptions& stepped_options, std::int64_t steps) {
    ExactSimulation exact(params, particles);
    const RunRecord exact_run = record_run(exact, steps);
    Simulation stepped(params, particles, stepped_options);
    return compare_to_exact(record_run(stepped, steps), exact_run, params);
}

}  // namespace particlesim
