#pragma once
// A scene scaled by 2^k: every length and speed times 2^k, exactly (no
// rounding inside the accepted range), so the rules give the scaled states.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cmath>
#include <vector>

inline void scale_by_power_of_two(particlesim::World& world, std::vector<particlesim::Particle>& particles, int k) {
    world = particlesim::World{std::ldexp(world.box_size, k), std::ldexp(world.radius, k)};
    for (particlesim::Particle& p : particles) {
        p.position = particlesim::Vec2(std::ldexp(p.position.x(), k), std::ldexp(p.position.y(), k));
        p.velocity = particlesim::Vec2(std::ldexp(p.velocity.x(), k), std::ldexp(p.velocity.y(), k));
    }
}
