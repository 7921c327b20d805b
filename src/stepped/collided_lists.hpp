#pragma once
// The list of a block's particles that collided this step, which the
// resolution works through: sixteen particles at a time where the processor
// has AVX-512 (compressed into the lists), else one at a time without a
// branch on each (which collide follows no pattern, and a branch on it is
// mispredicted for most that do). The same lists either way.

#include <cstddef>
#include <cstdint>

namespace particlesim {

// How many lanes list_collided() may write past the end of its lists.
inline constexpr std::size_t collided_lists_spill = 16;

struct CollidedCounts {
    std::size_t pairs = 0;
    std::size_t walls = 0;
};

// For the particles [first, last), by their partners (a stored index,
// wall_collision or no_collision; collision.hpp): into pair_at those whose
// partner comes after them (a pair is resolved once, at its lower index),
// into wall_at those that hit a wall, each in increasing order. Each list
// needs room for last - first + collided_lists_spill.
CollidedCounts list_collided(const std::uint32_t* partner, std::int64_t first, std::int64_t last,
                             std::uint32_t* pair_at, std::uint32_t* wall_at);

}  // namespace particlesim
