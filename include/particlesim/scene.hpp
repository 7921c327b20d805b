#pragma once
// A scene as read from input (io.md): its parameters and either the listed
// particles or, when none are listed, the number of particles to draw.

#include "particlesim/particle.hpp"
#include "particlesim/sim_params.hpp"

#include <cstddef>
#include <vector>

namespace particlesim {

struct Scene {
    SimParams params;
    std::size_t particle_count = 0;    // N
    std::vector<Particle> particles;   // index order; empty for a random scene
    long particle_count_line = 0;      // where N was read, for later messages

    [[nodiscard]] bool is_random() const { return particles.empty() && particle_count > 0; }
};

}  // namespace particlesim
