#pragma once
// Loads a scene from examples/ and runs it, keeping every state on the way.

#include "particlesim/scene_reader.hpp"
#include "particlesim/simulation.hpp"

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace example_scenes {

inline particlesim::Scene load(const std::string& name) {
    std::ifstream file(std::string(PARTICLESIM_EXAMPLES_DIR) + "/" + name);
    if (!file) throw std::runtime_error("cannot open example " + name);
    return particlesim::read_scene(file);
}

// states[s] is the state after step s (states[0]: the initial state).
inline std::vector<std::vector<particlesim::Particle>> run(const particlesim::Scene& scene,
                                                           const particlesim::SimOptions& options = {}) {
    particlesim::Simulation sim(scene.params, scene.particles, options);
    std::vector<std::vector<particlesim::Particle>> states{scene.particles};
    sim.run(scene.params.steps, [&](std::int64_t, std::span<const particlesim::Particle> particles) {
        states.emplace_back(particles.begin(), particles.end());
    });
    return states;
}

}  // namespace example_scenes
