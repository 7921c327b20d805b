#pragma once
// Counts the particles that overlap another one: the visible trace of the
// step rules' pass-through (real hard disks never overlap). Reuses its
// buffers, so counting after every step allocates nothing once warm.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

class OverlapCounter {
public:
    // The number of particles that overlap at least one other particle
    // (disks_overlap() of physics.hpp).
    std::uint64_t count(std::span<const Particle> particles, const World& world);

private:
    std::vector<std::uint32_t> cell_start_;
    std::vector<std::uint32_t> by_cell_;
    std::vector<std::uint32_t> cell_of_;
};

}  // namespace particlesim
