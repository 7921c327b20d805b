#pragma once
// FNV-1a over the exact bits of a state: positions, velocities, counters.

#include "particlesim/particle.hpp"

#include <cstdint>
#include <cstring>
#include <span>

namespace state_hash {

inline std::uint64_t hash(std::span<const particlesim::Particle> particles,
                          std::uint64_t seed = 14695981039346656037ULL) {
    std::uint64_t h = seed;
    const auto mix = [&h](const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t k = 0; k < size; ++k) h = (h ^ bytes[k]) * 1099511628211ULL;
    };
    for (const particlesim::Particle& p : particles) {
        const double values[] = {p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y()};
        mix(values, sizeof values);
        mix(&p.particle_collisions, sizeof p.particle_collisions);
        mix(&p.wall_collisions, sizeof p.wall_collisions);
    }
    return h;
}

}  // namespace state_hash
