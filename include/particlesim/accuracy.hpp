#pragma once
// How far a run is from real hard disks: its energy, the particles left
// overlapping, and the stepped engine (with its substeps) against the exact
// engine on the same start. Record each run once (record_run works with
// either engine), then compare the records.

#include "particlesim/engine.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace particlesim {

// Total kinetic energy (masses 1) at full precision (a compensated sum).
double total_kinetic_energy(std::span<const Particle> particles);
// The same sum taken over consecutive parts of the particles (as a
// distributed run hands them over): the same bits as over all at once.
class KineticEnergySum {
public:
    void add(std::span<const Particle> particles);
    [[nodiscard]] double total() const { return sum_ + compensation_; }

private:
    double sum_ = 0.0;
    double compensation_ = 0.0;
};
// (E - E0) / E0, or 0 when there was no energy to begin with.
double relative_energy_drift(double initial, double current);

// The positions of every particle after one step of a run.
struct PositionCheckpoint {
    std::int64_t step = 0;
    std::vector<Vec2> positions;
};

// What a run did, as the comparison needs it.
struct RunRecord {
    std::int64_t steps = 0;
    std::size_t particle_count = 0;
    std::uint64_t particle_collisions = 0;
    std::uint64_t wall_collisions = 0;
    std::uint64_t overlapping_particle_steps = 0;  // particles overlapping another, summed over the steps
    std::vector<PositionCheckpoint> checkpoints;   // those of the asked steps that the run reached
    double largest_energy_drift = 0.0;             // max over steps of |E - E0| / E0, at full precision
};

// Before chaos dominates: one step shows the error of a step, ten its growth.
inline constexpr std::int64_t default_checkpoints[] = {1, 10};

// Builds a RunRecord from the states a run shows after each step.
class RunRecorder {
public:
    RunRecorder(const World& world, std::span<const Particle> start, std::span<const std::int64_t> checkpoint_steps);
    ~RunRecorder();
    // Movable; a moved-from RunRecorder may only be assigned to or destroyed.
    RunRecorder(RunRecorder&&) noexcept;
    RunRecorder& operator=(RunRecorder&&) noexcept;

    // Throws std::invalid_argument when the particles are not as many as the start's.
    void observe(std::int64_t step, std::span<const Particle> particles, const StepCounts& step_counts);
    [[nodiscard]] const RunRecord& record() const;

private:
    class Measures;
    std::unique_ptr<Measures> measures_;
};

// Runs `steps` steps of the engine and records them.
template <Engine E>
RunRecord record_run(E& engine, std::int64_t steps,
                     std::span<const std::int64_t> checkpoint_steps = default_checkpoints) {
    RunRecorder recorder(engine.world(), engine.particles(), checkpoint_steps);
    run(engine, steps, [&](std::int64_t step, std::span<const Particle> particles) {
        recorder.observe(step, particles, engine.last_step());
    });
    return recorder.record();
}

// The RMS distance between the two runs' positions at a checkpoint, over L.
struct PositionError {
    std::int64_t step = 0;
    double rms_over_box = 0.0;
};

struct AccuracyReport {
    double particle_collision_rate_error = 0.0;  // (stepped - exact) / exact; 0 when both are 0
    double wall_collision_rate_error = 0.0;      // the same for walls: the pressure on the walls
    double overlap_fraction = 0.0;               // of the stepped run's particle-steps
    std::vector<PositionError> position_errors;  // at each checkpoint both runs reached
    double energy_drift = 0.0;                   // the stepped run's largest relative drift

    // The error at `step`; empty when it was not a checkpoint of both runs.
    [[nodiscard]] std::optional<double> position_error_at(std::int64_t step) const {
        for (const PositionError& e : position_errors) {
            if (e.step == step) return e.rms_over_box;
        }
        return std::nullopt;
    }
};

AccuracyReport compare_to_exact(const RunRecord& stepped, const RunRecord& exact, const World& world);

// Both runs from the same start, then the comparison. Throws OverlappingStart
// when the start has overlaps (the exact engine has no ground truth then).
AccuracyReport measure_accuracy(const World& world, const std::vector<Particle>& particles,
                                const SteppedOptions& stepped_options, std::int64_t steps,
                                std::span<const std::int64_t> checkpoint_steps = default_checkpoints);

}  // namespace particlesim
