#pragma once
// The wall hits of a step resolved four particles at a time, in the eight
// double lanes of AVX-512 (two a particle, as MotionLanes has them): the
// bounce off the first wall, then the rest of the step stopping at the next
// one. The same IEEE operations on the same values, lane by lane, so the
// same bits as resolve_wall() one particle at a time. A sparse scene's step
// has about a quarter of its particles hit a wall, each through two
// divisions and their selects.

#include "particlesim/particle.hpp"

#include <cstddef>
#include <cstdint>

namespace particlesim {

struct Box;

// Resolves the wall hits of particles[wall_at[k]] for k below `count`, four
// at a time while four remain, each hitting at collision_time[wall_at[k]]
// within a step of `duration`: bounced, moved on for the rest of the step
// (stopping at a wall it reaches), its wall collisions counted. Returns how
// many it resolved (the first ones, a multiple of four; none without the
// lanes, avx512_lanes_available()). The particles must differ.
std::size_t resolve_walls_four_at_a_time(Particle* particles, const std::uint32_t* wall_at, std::size_t count,
                                         const double* collision_time, const Box& box, double duration);

}  // namespace particlesim
