#include "trajectory.hpp"

#include "shortest_number.hpp"

namespace simcli {

namespace {

// Any species name does for OVITO; ASE needs a chemical symbol.
constexpr const char* species = "Ar";

}  // namespace

Trajectory::Trajectory(const std::string& path, const particlesim::World& world, particlesim::Boundary boundary,
                       std::int64_t every, std::int64_t last_step)
    : file_(path),
      world_(world),
      pbc_(boundary == particlesim::Boundary::periodic ? "T T F" : "F F F"),
      every_(every),
      last_step_(last_step) {}

void Trajectory::observe(std::int64_t step, std::span<const particlesim::Particle> particles) {
    if (step % every_ != 0 && step != last_step_) return;
    const double side = world_.box_size;
    text_.clear();
    text_ += std::to_string(particles.size());
    // The third cell vector spans one diameter: the disks as a slab, for viewers that want a volume.
    text_ += "\nLattice=\"";
    for (const double value : {side, 0.0, 0.0, 0.0, side, 0.0, 0.0, 0.0, 2.0 * world_.radius}) {
        append_shortest(text_, value);
        text_ += ' ';
    }
    text_.back() = '"';  // in place of the last space
    text_ += " Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1 pbc=\"";
    text_ += pbc_;
    text_ += "\" step=";
    text_ += std::to_string(step);
    text_ += " time=";
    append_shortest(text_, static_cast<double>(step));
    text_ += '\n';
    for (const particlesim::Particle& p : particles) {
        text_ += species;
        for (const double value :
             {p.position.x(), p.position.y(), 0.0, p.velocity.x(), p.velocity.y(), 0.0, world_.radius}) {
            text_ += ' ';
            append_shortest(text_, value);
        }
        text_ += '\n';
    }
    file_.write(text_, "trajectory");
}

void Trajectory::commit() { file_.commit(); }

}  // namespace simcli
