#include "observables_file.hpp"

#include "shortest_number.hpp"

#include <algorithm>

namespace simcli {

ObservablesFile::ObservablesFile(const std::string& path, const particlesim::World& world,
                                 particlesim::Boundary boundary, std::int64_t every, std::int64_t last_step,
                                 std::int64_t measure_from)
    : file_(path),
      world_(world),
      boundary_(boundary),
      every_(every),
      last_step_(last_step),
      measure_from_(measure_from) {
    text_ = "step,time,pair_collisions,wall_collisions,kinetic_energy,betaP_d2,Z,psi6";
    text_ += periodic() ? "\n" : ",betaP_d2_walls,Z_walls\n";
    file_.write(text_, "observables");
}

void ObservablesFile::start(std::int64_t step, const particlesim::StepCounts& totals,
                            const particlesim::CollisionSums& sums) {
    previous_step_ = step;
    previous_totals_ = totals;
    previous_sums_ = sums;
}

void ObservablesFile::observe(std::int64_t step, std::span<const particlesim::Particle> particles,
                              const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums) {
    if (step % every_ == 0 || step == last_step_) write_row(step, particles, totals, sums);
}

void ObservablesFile::end_at(std::int64_t step, std::span<const particlesim::Particle> particles,
                             const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums) {
    if (step > previous_step_) write_row(step, particles, totals, sums);
}

void ObservablesFile::write_row(std::int64_t step, std::span<const particlesim::Particle> particles,
                                const particlesim::StepCounts& totals, const particlesim::CollisionSums& sums) {
    double kinetic = 0.0;
    for (const particlesim::Particle& p : particles) kinetic += 0.5 * p.velocity.squaredNorm();
    const double duration = static_cast<double>(step - previous_step_);
    const particlesim::Pressure pressure =
        particlesim::box_pressure(world_, boundary_, particles.size(), kinetic, particlesim::total_momentum(particles),
                                  sums - previous_sums_, duration);
    text_.clear();
    text_ += std::to_string(step) + ',';
    append_shortest(text_, static_cast<double>(step));
    text_ += ',' + std::to_string(totals.particle_collisions - previous_totals_.particle_collisions);
    text_ += ',' + std::to_string(totals.wall_collisions - previous_totals_.wall_collisions);
    for (const double value :
         {kinetic, pressure.betaP_d2, pressure.Z, particlesim::hexatic_order(particles, world_, boundary_)}) {
        text_ += ',';
        append_shortest(text_, value);
    }
    if (!periodic()) {
        for (const double value : {pressure.betaP_d2_walls, pressure.Z_walls}) {
            text_ += ',';
            append_shortest(text_, value);
        }
    }
    text_ += '\n';
    file_.write(text_, "observables");
    if (previous_step_ >= measure_from_) {
        virial_rows_.push_back(pressure.betaP_d2);
        wall_rows_.push_back(pressure.betaP_d2_walls);
    }
    previous_step_ = step;
    previous_totals_ = totals;
    previous_sums_ = sums;
}

void ObservablesFile::commit() { file_.commit(); }

namespace {

// `blocks` blocks where the rows allow, fewer (at least two rows each) where they do not.
particlesim::MeanWithError blocked(const std::vector<double>& rows, std::size_t blocks) {
    return particlesim::block_average(rows, std::min<std::size_t>(blocks, rows.size() / 2));
}

}  // namespace

particlesim::MeanWithError ObservablesFile::virial_pressure(std::size_t blocks) const {
    return blocked(virial_rows_, blocks);
}
particlesim::MeanWithError ObservablesFile::wall_pressure() const { return blocked(wall_rows_, 16); }

}  // namespace simcli
