#pragma once
// --observables FILE.csv: a header, then a row every --observe-every K steps
// (and at the last step) of what a researcher plots: the collisions of the
// interval since the row before, the kinetic energy, the pressure of the
// interval by the virial and by the walls (as beta P (2r)^2 and
// Z = beta P A / N), and the hexatic order |psi6| at the row's step
// (particlesim/observables.hpp). The rows from --measure-from on feed
// --stats' pressure with its error bar. Written like -o; a run resumed
// from a checkpoint writes the rows after the checkpoint's step.

#include "output_file.hpp"

#include "particlesim/engine.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace simcli {

class ObservablesFile {
public:
    // Throws particlesim::OutputError.
    ObservablesFile(const std::string& path, const particlesim::World& world, particlesim::Boundary boundary,
                    std::int64_t every, std::int64_t last_step, std::int64_t measure_from);

    // The run's first step (0, or a checkpoint's): the first row's interval
    // begins here. Every later step: a row at each multiple of K and the last.
    void start(std::int64_t step, const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums);
    void observe(std::int64_t step, std::span<const particlesim::Particle> particles,
                 const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums);
    // An interrupted run's last row: the interval since the row before, so
    // that its rows and a resumed run's cover every step once.
    void end_at(std::int64_t step, std::span<const particlesim::Particle> particles,
                const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums);
    // Puts the file in place. Throws particlesim::OutputError.
    void commit();
    // At a checkpoint: the rows so far on disk, in place (OutputFile::keep_so_far).
    std::optional<OutputFile::Extent> keep_so_far() { return file_.keep_so_far(); }
    // Where the row that the next one ends began: its step, and the totals and sums then.
    [[nodiscard]] std::int64_t open_row_step() const { return previous_step_; }
    [[nodiscard]] const particlesim::StepCounts& open_row_totals() const { return previous_totals_; }
    [[nodiscard]] const particlesim::CollisionSums& open_row_sums() const { return previous_sums_; }

    // Over the rows from measure_from on, in 16 blocks where the rows allow
    // (the walls' route: a walled box only). The virial's in fewer, longer
    // blocks too: an error that grows with the blocks' length says that
    // they are shorter than the pressure's correlations.
    [[nodiscard]] particlesim::MeanWithError virial_pressure(std::size_t blocks = 16) const;
    [[nodiscard]] particlesim::MeanWithError wall_pressure() const;
    [[nodiscard]] bool periodic() const { return boundary_ == particlesim::Boundary::periodic; }
    [[nodiscard]] std::int64_t measure_from() const { return measure_from_; }

private:
    void write_row(std::int64_t step, std::span<const particlesim::Particle> particles,
                   const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums);

    OutputFile file_;
    particlesim::World world_;
    particlesim::Boundary boundary_;
    std::int64_t every_;
    std::int64_t last_step_;
    std::int64_t measure_from_;
    std::int64_t previous_step_ = 0;
    particlesim::StepCounts previous_totals_;
    particlesim::CollisionSums previous_sums_;
    std::vector<double> virial_rows_, wall_rows_;  // beta P (2r)^2 of the measured rows
    std::string text_;
};

}  // namespace simcli
