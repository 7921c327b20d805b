#pragma once
// A scene the tests and benchmarks run by name: the world, how many steps,
// the particles.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <string>
#include <vector>

struct NamedScene {
    std::string name;
    particlesim::World world;
    std::int64_t steps = 0;
    std::vector<particlesim::Particle> particles;
    bool overlapping = false;  // two disks overlap at the start: the exact engine refuses it
};
