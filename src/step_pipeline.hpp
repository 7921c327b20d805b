#pragma once
// The stages of one step (rules.md "One step"), each a function with one job:
//   detect  : wall candidates here, pair candidates in a pair search
//   order   : sort by (t, kind, i, j)
//   select  : greedy, one collision per particle
//   resolve : bounce / exchange, then the rest of the step stopping at walls
//   advance : every particle without a collision moves freely
// None of them allocates once its vectors have reached their working size.

#include "box.hpp"
#include "collision.hpp"
#include "pair_search.hpp"
#include "particlesim/particle.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

// Writes each particle's first wall time into `wall_time` and appends the
// wall candidates (time <= duration) to `candidates`, in index order.
void detect_wall_candidates(std::span<const Particle> particles, const Box& box, double duration,
                            std::span<double> wall_time, std::vector<Collision>& candidates, int threads);

// Appends the pair candidates found by each thread to `candidates`, sorts all
// by the total order and removes the duplicates a pair search may produce.
// Busy steps sort the lists on up to `threads` threads and merge them, with
// the wall candidates moved to `scratch` meanwhile. When the particles are
// not stored in the user's order, ties are broken by their user indices:
// `user_index` maps stored places to user indices, `stored_index` back (see
// StorageOrder); both empty when the two orders are the same. A pair's
// stored indices may then come in either order.
void order_candidates(std::vector<Collision>& candidates, std::span<ThreadCandidates> found,
                      std::vector<Collision>& scratch, std::span<const std::uint32_t> user_index,
                      std::span<const std::uint32_t> stored_index, int threads);

// Accepts, in order, each candidate whose particles are still free, and
// marks each of its particles with its number in `accepted` (from 1; 0 is
// free).
void select_collisions(std::span<const Collision> ordered, std::span<std::uint32_t> collision_of,
                       std::vector<Collision>& accepted);

// Carries out every accepted collision and the rest of the step of its particles.
void resolve_collisions(std::span<Particle> particles, std::span<const std::uint32_t> collision_of,
                        std::span<const Collision> accepted, const Box& box, double duration, int threads);

// Moves every particle without a collision, and clears the marks of the others.
void advance_free_particles(std::span<Particle> particles, std::span<std::uint32_t> collision_of, const Box& box,
                            double duration, int threads);

}  // namespace particlesim
