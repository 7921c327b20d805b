#pragma once
// What one step (or a whole run, summed) did, in either engine.

#include <cstdint>

namespace particlesim {

struct StepCounts {
    std::uint64_t pair_tests = 0;  // contact-time evaluations
    std::uint64_t candidates = 0;  // stepped: distinct candidates; exact: events predicted
    std::uint64_t particle_collisions = 0;
    std::uint64_t wall_collisions = 0;

    StepCounts& operator+=(const StepCounts& other) {
        pair_tests += other.pair_tests;
        candidates += other.candidates;
        particle_collisions += other.particle_collisions;
        wall_collisions += other.wall_collisions;
        return *this;
    }
};

}  // namespace particlesim
