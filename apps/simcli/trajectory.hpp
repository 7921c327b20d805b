#pragma once
// --trajectory FILE.xyz: the run's states every K steps as extended XYZ
// frames, the format OVITO and ASE read: per frame the particle count, a
// line with the box (`Lattice`, `pbc`), the columns (`Properties`) and the
// frame's step and time, then one line per disk: species, position,
// velocity (z = 0: the disks are 2D) and radius. Numbers in the shortest
// text that reads back to the same double. Written like -o: to a temporary
// file put in place when the run ends.

#include "output_file.hpp"

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace simcli {

class Trajectory {
public:
    // Frames at steps 0, K, 2K, ... and the last step. Throws particlesim::OutputError.
    Trajectory(const std::string& path, const particlesim::World& world, particlesim::Boundary boundary,
               std::int64_t every, std::int64_t last_step);

    void observe(std::int64_t step, std::span<const particlesim::Particle> particles);
    // Puts the file in place. Throws particlesim::OutputError.
    void commit();
    // At a checkpoint: the frames so far on disk, in place (OutputFile::keep_so_far).
    std::optional<OutputFile::Extent> keep_so_far() { return file_.keep_so_far(); }

private:
    OutputFile file_;
    particlesim::World world_;
    const char* pbc_;  // "F F F" or "T T F"
    std::int64_t every_;
    std::int64_t last_step_;
    std::string text_;  // one frame
};

}  // namespace simcli
