#pragma once
// One hard disk: position, velocity (length per step) and its two collision
// counters (rules.md "World").

#include <Eigen/Core>

#include <cstdint>

namespace particlesim {

using Vec2 = Eigen::Vector2d;

struct Particle {
    Vec2 position = Vec2::Zero();
    Vec2 velocity = Vec2::Zero();
    std::uint64_t particle_collisions = 0;  // pc
    std::uint64_t wall_collisions = 0;      // wc
};

}  // namespace particlesim
