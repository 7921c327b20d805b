#pragma once
// Random dense packings by Lubachevsky-Stillinger growth (Lubachevsky &
// Stillinger, J. Stat. Phys. 60, 561 (1990)): disks start as points at
// random, move and collide event by event while every radius grows at the
// same rate, until they fill the area fraction asked for. A slow growth
// lets the disks stay near equilibrium (at high density they order); a fast
// one jams them in a random packing below close packing.

#include "particlesim/particle.hpp"

#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

namespace particlesim {

// Slow enough that a packing of 0.7 forms from a liquid that kept up with
// its compression, fast enough for 1e4 disks in seconds (docs/physics.md).
inline constexpr double default_growth_rate = 0.01;

struct GrowthRequest {
    std::size_t count = 0;
    double area_fraction = 0.5;  // reached with every gap at least 1e-9 of a diameter
    // The diameter's growth per unit time, in units where kT = 1 and the
    // mass is 1 (speeds about 1): Lubachevsky-Stillinger's rate.
    double growth_rate = default_growth_rate;
    bool periodic = false;
    std::uint64_t seed = 1;
    // Called every N events (at least 64) with the area fraction the disks
    // fill then, rising towards area_fraction, and area_fraction: to show
    // progress. It does not change the packing.
    std::function<void(double reached, double target)> progress;
};

// The densest packing of disks in the plane, the triangular lattice's: pi / (2 sqrt 3).
inline constexpr double close_packing_fraction = std::numbers::pi / (2.0 * std::numbers::sqrt3);

struct GrownPacking {
    double box_size = 0.0;  // sqrt(N): a number density of 1
    std::vector<Vec2> centres;
};

// Throws std::invalid_argument when the packing cannot be grown: a fraction
// outside (0, close packing], a periodic box under five diameters wide, or
// disks that jam first (the message names the fraction they reached).
GrownPacking grow_packing(const GrowthRequest& request);

}  // namespace particlesim
