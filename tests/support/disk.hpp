#pragma once
// A disk at (x, y) with velocity (vx, vy), for scenes built by hand.

#include "particlesim/particle.hpp"

namespace test_scenes {

inline particlesim::Particle disk(double x, double y, double vx = 0.0, double vy = 0.0) {
    particlesim::Particle p;
    p.position = particlesim::Vec2(x, y);
    p.velocity = particlesim::Vec2(vx, vy);
    return p;
}

}  // namespace test_scenes
