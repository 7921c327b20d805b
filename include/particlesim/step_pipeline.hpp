#pragma once
// The stages of one step (rules.md "One step"), each a function with one job:
//   detect  : wall candidates here, pair candidates in a pair search
//   order   : sort by (t, kind, i, j)
//   select  : greedy, one collision per particle
//   resolve : bounce / exchange, then the rest of the step stopping at walls
//   advance : every particle without a collision moves freely
// None of them allocates once its vectors have reached their working size.

#include "particlesim/box.hpp"
#include "particlesim/collision.hpp"
#include "particlesim/pair_search.hpp"
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
// the wall candidates moved to `scratch` meanwhile.
void order_candidates(std::vector<Collision>& candidates, std::span<ThreadCandidates> found,
                      std::vector<Collision>& scratch, int threads);

// Accepts, in order, each candidate whose particles are still free and marks
// them `busy`.
void select_collisions(std::span<const Collision> ordered, std::span<std::uint8_t> busy,
                       std::vector<Collision>& accepted);

// Carries out every accepted collision and the rest of the step of its particles.
void resolve_collisions(std::span<Particle> particles, std::span<const Collision> accepted, const Box& box,
                        double duration, int threads);

// Moves every particle that is not `busy`, then clears the marks of `accepted`.
void advance_free_particles(std::span<Particle> particles, std::span<std::uint8_t> busy,
                            std::span<const Collision> accepted, const Box& box, double duration, int threads);

}  // namespace particlesim
