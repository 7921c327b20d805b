#pragma once
// simcli --snapshot FILE.svg [--snapshot-step N]: one state as an SVG picture
// for documents: the box, the disks to scale (at least a visible size),
// coloured by speed, with a caption.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace simcli {

// Writes atomically, like -o. Throws particlesim::OutputError.
void write_snapshot(const std::string& path, const particlesim::World& world,
                    std::span<const particlesim::Particle> particles, std::int64_t step);

}  // namespace simcli
