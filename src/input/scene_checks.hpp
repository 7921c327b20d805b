#pragma once
// The check every engine makes of the scene it is given (rules.md "World"),
// and the most particles a scene may have on this machine.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstddef>
#include <cstdint>
#include <span>

namespace particlesim {

// The most particles this machine can hold (bounded by memory and by the
// 32-bit particle indices), so that a scene's N is refused, read or made,
// before anything is allocated for it.
std::size_t max_particle_count();

// Throws std::invalid_argument, its message starting with `engine`, for a
// scene that breaks the rules or leaves the accepted range (world.hpp): L or r
// outside [1e-60, 1e60] or 2r > L, a centre outside [r, L - r], a velocity
// component beyond 1e60 (or NaN), more particles than 32-bit indices can name.
// In a periodic box the centres lie in [0, L) instead, or, for a saved state
// (each particle where it was at its own time stamp), within a side of it.
enum class CentresIn : std::uint8_t { walled_box, periodic_box, periodic_saved };
void require_valid_scene(const char* engine, const World& world, std::span<const Particle> particles,
                         CentresIn centres = CentresIn::walled_box);

}  // namespace particlesim
