#pragma once
// simcli --snapshot FILE.svg [--snapshot-step N]: one state as an SVG picture
// for documents: the box, the disks to scale (at least a visible size),
// coloured by speed or by the local psi6 (colour_by.hpp), with a caption of
// two lines. Written in pixels (the box 720 wide, y upwards), whatever L.

#include "colour_by.hpp"

#include "particlesim/observables.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace simcli {

// Writes atomically, like -o. Throws particlesim::OutputError.
void write_snapshot(const std::string& path, const particlesim::World& world,
                    std::span<const particlesim::Particle> particles, std::int64_t step,
                    ColourBy colour_by = ColourBy::speed,
                    particlesim::Boundary boundary = particlesim::Boundary::walls);

}  // namespace simcli
