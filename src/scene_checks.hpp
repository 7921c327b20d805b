#pragma once
// The check every engine makes of the scene it is given (rules.md "World").

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <span>

namespace particlesim {

// Throws std::invalid_argument, its message starting with `engine`, for a
// scene that breaks the rules: bad L or r, a centre outside [r, L - r], a
// non-finite velocity, or more particles than 32-bit indices can name.
void require_valid_scene(const char* engine, const World& world, std::span<const Particle> particles);

}  // namespace particlesim
