#pragma once
// The check every engine makes of the scene it is given (rules.md "World").

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <span>

namespace particlesim {

// Throws std::invalid_argument, its message starting with `engine`, for a
// scene that breaks the rules or leaves the accepted range (world.hpp): L or r
// outside [1e-60, 1e60] or 2r > L, a centre outside [r, L - r], a velocity
// component beyond 1e60 (or NaN), more particles than 32-bit indices can name.
void require_valid_scene(const char* engine, const World& world, std::span<const Particle> particles);

}  // namespace particlesim
