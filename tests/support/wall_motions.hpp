#pragma once
// Random coordinates and velocity components for tests of the motion at the
// walls: an eighth of the coordinates exactly on each wall, the rest inside;
// an eighth of the components 0, an eighth +-2 (exact times), the rest
// uniform in (-spread / 2, spread / 2).

#include "core/box.hpp"
#include "core/random.hpp"

#include <cstdint>

namespace test_scenes {

inline double wall_coordinate(particlesim::SplitMix64& rng, const particlesim::Box& box) {
    const std::uint64_t kind = rng.next() % 8;
    if (kind == 0) return box.lower;
    if (kind == 1) return box.upper;
    return box.lower + (box.upper - box.lower) * rng.uniform();
}

inline double wall_speed(particlesim::SplitMix64& rng, double spread) {
    const std::uint64_t kind = rng.next() % 8;
    if (kind == 0) return 0.0;
    if (kind == 1) return rng.next() % 2 == 0 ? 2.0 : -2.0;
    return spread * (rng.uniform() - 0.5);
}

}  // namespace test_scenes
