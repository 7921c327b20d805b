#pragma once
// The free flight of advance_free_particles() four particles at a time, in
// the eight double lanes of AVX-512 (two a particle, as MotionLanes has
// them): the same IEEE operations on the same values, lane by lane, so the
// same bits as one particle at a time. A sparse scene's step moves every
// particle and measures its next wall time; one at a time, the loop's
// moves between registers and its two-lane division set its pace.

#include "particlesim/particle.hpp"

#include <cstdint>

namespace particlesim {

struct Box;

// For particles [first, last), four at a time while four remain: moves each
// whose partner is no_collision for `step` (the others, resolved already,
// for +0.0), sets every partner to no_collision, writes each wall time
// (time_to_wall()'s) to wall_time, and adds to wall_candidates those at or
// before `step`. Returns the end of the particles it moved: first plus a
// multiple of four, first itself without the lanes (avx512_lanes_available()).
std::int64_t fly_four_at_a_time(Particle* particles, std::uint32_t* partner, double* wall_time, const Box& box,
                                double step, std::int64_t first, std::int64_t last, std::uint32_t& wall_candidates);

}  // namespace particlesim
