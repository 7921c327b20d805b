#pragma once
// Counts the particles that overlap another one: the visible trace of the
// step rules' pass-through (real hard disks never overlap). Reuses its
// buffers, so counting after every step allocates nothing once warm.

#include "particlesim/particle.hpp"
#include "particlesim/sim_params.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

// Two disks overlap when their centres are closer than 2r by more than this
// fraction: shallower overlaps are rounding at a contact, not pass-through.
inline constexpr double overlap_tolerance = 1e-6;

class OverlapCounter {
public:
    // The number of particles that overlap at least one other particle.
    std::uint64_t count(std::span<const Particle> particles, const SimParams& params);

private:
    std::vector<std::uint32_t> cell_start_;
    std::vector<std::uint32_t> by_cell_;
    std::vector<std::uint32_t> cell_of_;
};

}  // namespace particlesim
