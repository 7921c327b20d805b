#include "particlesim/accuracy.hpp"

#include "measure/overlap_counter.hpp"
#include "particlesim/exact_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace particlesim {

// What the recorder measures after each step, with the buffers it reuses.
class RunRecorder::Measures {
public:
    Measures(const World& world, std::span<const Particle> start, std::span<const std::int64_t> checkpoint_steps)
        : world_(world),
          initial_energy_(total_kinetic_energy(start)),
          checkpoint_steps_(checkpoint_steps.begin(), checkpoint_steps.end()) {
        record_.particle_count = start.size();
    }

    void observe(std::int64_t step, std::span<const Particle> particles, const StepCounts& step_counts) {
        if (particles.size() != record_.particle_count) {
            throw std::invalid_argument("particlesim::RunRecorder: observed " + std::to_string(particles.size()) +
                                        " particles, but the run started with " +
                                        std::to_string(record_.particle_count));
        }
        record_.steps = step;
        record_.particle_collisions += step_counts.particle_collisions;
        record_.wall_collisions += step_counts.wall_collisions;
        record_.overlapping_particle_steps += overlaps_.count(particles, world_);
        const double drift = std::abs(relative_energy_drift(initial_energy_, total_kinetic_energy(particles)));
        record_.largest_energy_drift = std::max(record_.largest_energy_drift, drift);
        if (std::find(checkpoint_steps_.begin(), checkpoint_steps_.end(), step) != checkpoint_steps_.end()) {
            PositionCheckpoint& checkpoint = record_.checkpoints.emplace_back();
            checkpoint.step = step;
            checkpoint.positions.reserve(particles.size());
            for (const Particle& p : particles) checkpoint.positions.push_back(p.position);
        }
    }

    const RunRecord& record() const { return record_; }

private:
    World world_;
    double initial_energy_;
    std::vector<std::int64_t> checkpoint_steps_;
    OverlapCounter overlaps_;
    RunRecord record_;
};

RunRecorder::RunRecorder(const World& world, std::span<const Particle> start,
                         std::span<const std::int64_t> checkpoint_steps)
    : measures_(std::make_unique<Measures>(world, start, checkpoint_steps)) {}
RunRecorder::~RunRecorder() = default;
RunRecorder::RunRecorder(RunRecorder&&) noexcept = default;
RunRecorder& RunRecorder::operator=(RunRecorder&&) noexcept = default;

void RunRecorder::observe(std::int64_t step, std::span<const Particle> particles, const StepCounts& step_counts) {
    measures_->observe(step, particles, step_counts);
}
const RunRecord& RunRecorder::record() const { return measures_->record(); }

namespace {

double relative_error(std::uint64_t measured, std::uint64_t truth) {
    if (truth == 0) return measured == 0 ? 0.0 : std::numeric_limits<double>::infinity();
    return (static_cast<double>(measured) - static_cast<double>(truth)) / static_cast<double>(truth);
}

double rms_distance_over_box(const std::vector<Vec2>& a, const std::vector<Vec2>& b, double box_size) {
    if (a.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]).squaredNorm();
    return std::sqrt(sum / static_cast<double>(a.size())) / box_size;
}

}  // namespace

AccuracyReport compare_to_exact(const RunRecord& stepped, const RunRecord& exact, const World& world) {
    if (stepped.steps != exact.steps) throw std::invalid_argument("compare_to_exact: the runs have different lengths");
    if (stepped.particle_count != exact.particle_count) {
        throw std::invalid_argument("compare_to_exact: the runs have different particle counts");
    }
    AccuracyReport report;
    report.particle_collision_rate_error = relative_error(stepped.particle_collisions, exact.particle_collisions);
    report.wall_collision_rate_error = relative_error(stepped.wall_collisions, exact.wall_collisions);
    const double particle_steps = static_cast<double>(stepped.particle_count) * static_cast<double>(stepped.steps);
    report.overlap_fraction =
        particle_steps > 0.0 ? static_cast<double>(stepped.overlapping_particle_steps) / particle_steps : 0.0;
    for (const PositionCheckpoint& mine : stepped.checkpoints) {
        for (const PositionCheckpoint& truth : exact.checkpoints) {
            if (truth.step != mine.step) continue;
            report.position_errors.push_back(
                {mine.step, rms_distance_over_box(mine.positions, truth.positions, world.box_size)});
        }
    }
    report.energy_drift = stepped.largest_energy_drift;
    return report;
}

AccuracyReport measure_accuracy(const World& world, const std::vector<Particle>& particles,
                                const SteppedOptions& stepped_options, std::int64_t steps,
                                std::span<const std::int64_t> checkpoint_steps) {
    ExactSimulation exact(world, particles);
    const RunRecord exact_run = record_run(exact, steps, checkpoint_steps);
    SteppedSimulation stepped(world, particles, stepped_options);
    return compare_to_exact(record_run(stepped, steps, checkpoint_steps), exact_run, world);
}

}  // namespace particlesim
