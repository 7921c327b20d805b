#pragma once
// Loads a scene from examples/ and runs it with either engine, keeping every
// state on the way.

#include "particlesim/exact_simulation.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace example_scenes {

using States = std::vector<std::vector<particlesim::Particle>>;

inline particlesim::Scene load(const std::string& name) {
    std::ifstream file(std::string(PARTICLESIM_EXAMPLES_DIR) + "/" + name);
    if (!file) throw std::runtime_error("cannot open example " + name);
    return particlesim::read_scene(file);
}

// states[s] is the state after step s (states[0]: the initial state).
template <typename Engine>
States states_of(Engine& engine, std::int64_t steps) {
    States states{{engine.particles().begin(), engine.particles().end()}};
    particlesim::run(engine, steps, [&](std::int64_t, std::span<const particlesim::Particle> particles) {
        states.emplace_back(particles.begin(), particles.end());
    });
    return states;
}

inline States run(const particlesim::Scene& scene, const particlesim::SteppedOptions& options = {}) {
    particlesim::SteppedSimulation sim(scene.world, scene.particles, options);
    return states_of(sim, scene.steps);
}

inline States run_exact(const particlesim::Scene& scene) {
    particlesim::ExactSimulation sim(scene.world, scene.particles);
    return states_of(sim, scene.steps);
}

}  // namespace example_scenes
