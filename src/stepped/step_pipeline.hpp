#pragma once
// The stages of one step (rules.md "One step"), each a function with one job:
//   detect  : wall candidates here, pair candidates in a pair search
//   order   : (t, kind, i, j), compared where candidates share a particle
//   select  : greedy, one collision per particle
//   resolve : bounce / exchange, then the rest of the step stopping at walls
//   advance : every particle without a collision moves freely
// None of them allocates once its vectors have reached their working size.

#include "core/box.hpp"
#include "core/collision.hpp"
#include "particlesim/engine.hpp"
#include "particlesim/particle.hpp"
#include "search/pair_search.hpp"
#include "stepped/step_start.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace particlesim {

// Writes each particle's first wall time into `wall_time`, and the blocks'
// figures into `start` (step_start.hpp); for a step whose previous one did
// not measure them (advance_free_particles).
void measure_step_start(std::span<const Particle> particles, const Box& box, double duration,
                        std::span<double> wall_time, StepStart& start, int threads);

// Appends the wall candidates (wall time <= duration) to `candidates`, in
// index order, from the measured start.
void gather_wall_candidates(std::span<const double> wall_time, double duration, StepStart& start,
                            std::vector<Collision>& candidates, int threads);

// rules.md "Order" between two candidates: time, walls before pairs, then
// the lowest user indices. `user_index` maps stored places to user indices
// (StorageOrder); empty while the two orders are the same.
class CandidateOrder {
public:
    explicit CandidateOrder(std::span<const std::uint32_t> user_index) : user_index_(user_index) {}

    // The user's index of each stored place; empty while the two orders are the same.
    [[nodiscard]] std::span<const std::uint32_t> user_index() const { return user_index_; }

    [[nodiscard]] bool before(const Collision& a, const Collision& b) const {
        if (a.time != b.time) return a.time < b.time;
        if (a.kind != b.kind) return a.kind < b.kind;
        return user_indices(a) < user_indices(b);
    }

private:
    [[nodiscard]] std::pair<std::uint32_t, std::uint32_t> user_indices(const Collision& c) const {
        if (user_index_.empty()) return {c.i, c.j};
        if (c.kind == CollisionKind::wall) return {user_index_[c.i], 0};
        return std::minmax(user_index_[c.i], user_index_[c.j]);
    }

    std::span<const std::uint32_t> user_index_;
};

// Whether no collision is decided yet for any particle of candidate c:
// otherwise c is ruled out (`partner` as select_collisions leaves it).
inline bool undecided(const Collision& c, std::span<const std::uint32_t> partner) {
    return partner[c.i] == no_collision && (c.kind == CollisionKind::wall || partner[c.j] == no_collision);
}

// Whether a round of the selection stalled: it left more than half of the
// `before` candidates undecided. Rounds cost every undecided candidate
// each, so they pay while they halve them; where one does not (disks piled
// on one another: every pair a candidate at t = 0, accepted in index order,
// one pair a round, N / 2 rounds of N^2 candidates), the rest are decided
// in one walk of the order.
inline bool selection_stalled(std::size_t before, std::size_t left) { return 2 * left > before; }

// select_collisions' buffers, kept between steps so that a step allocates
// nothing.
struct SelectionScratch {
    explicit SelectionScratch(std::size_t particles = 0) : earliest(particles, no_collision) {}

    std::vector<std::uint32_t> earliest;  // by particle: its first candidate; no_collision between calls
    std::vector<StepCounts> block_counts;
    std::vector<std::uint32_t> block_kept;
};

// rules.md "Select" without sorting: the greedy pass over the ordered
// candidates accepts a candidate exactly when no accepted one shares a
// particle with it and comes first. A candidate that comes first among all
// candidates of its particles is therefore accepted; the candidates that
// share a particle with it are then out, and the same holds again among the
// rest. Rounds of "accept every such candidate, drop what they rule out"
// accept exactly the greedy pass's collisions, each round O(candidates).
//
// The rounds' passes run on up to `threads` threads; the result does not
// depend on how many.
//
// `candidates` holds the wall candidates on entry; each thread's pair
// candidates are appended (duplicates are harmless: equal candidates keep
// the first). Each particle gets its partner's stored index (or
// no_collision / wall_collision, collision.hpp) and, for an accepted
// collision, its time in
// `collision_time`. Returns the accepted collisions counted by kind.
StepCounts select_collisions(std::vector<Collision>& candidates, std::span<const ThreadCandidates> found,
                             const CandidateOrder& order, std::span<std::uint32_t> partner,
                             std::span<double> collision_time, SelectionScratch& scratch, int threads);

// Carries out every accepted collision (`accepted` counts them: a second
// thread only for enough of them) and the rest of the step of its particles.
void resolve_collisions(std::span<Particle> particles, std::span<const std::uint32_t> partner,
                        std::span<const double> collision_time, const StepCounts& accepted, const Box& box,
                        double duration, int threads);

// Moves every particle without a collision, sets every partner back to
// no_collision, and in the same pass measures the start of the next step of
// `duration` (as measure_step_start()): one pass over the particles fewer.
void advance_free_particles(std::span<Particle> particles, std::span<std::uint32_t> partner, const Box& box,
                            double duration, std::span<double> wall_time, StepStart& next, int threads);

}  // namespace particlesim
