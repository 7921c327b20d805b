#pragma once
// Which pair search `PairSearch::automatic` takes: brute force for a handful
// of particles; otherwise the cheaper of the paths search and the grid by a
// cost model of a micro-step, from the scene's size, density and speeds
// (stepped_tuning.hpp holds its constants and where they were measured).
// Every search gives the same candidates, so the choice changes the time,
// never the output.

#include "particlesim/particle.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "particlesim/world.hpp"

#include <span>

namespace particlesim {

// The model's inputs and costs for one scene, in nanoseconds a micro-step.
struct SearchCosts {
    double new_lines = 0.0;  // expected lines changed a micro-step: wall hits + 2 x pair collisions
    int slices = 1;          // the grid's time slices a micro-step
    double paths_ns = 0.0;
    double grid_ns = 0.0;
};

[[nodiscard]] SearchCosts estimate_search_costs(const World& world, std::span<const Particle> particles, int substeps);

[[nodiscard]] PairSearch automatic_search(const World& world, std::span<const Particle> particles, int substeps);

}  // namespace particlesim
