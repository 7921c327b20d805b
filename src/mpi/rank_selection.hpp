#pragma once
// rules.md "Select" when the particles are spread over ranks: each rank
// holds the candidates of the particles it owns (with copies, "ghosts", of
// the other ranks' particles they may meet), and the ranks decide together,
// in rounds, exactly what the one-process greedy pass accepts.
//
// Why it is the same: the greedy pass accepts a candidate exactly when no
// accepted candidate that shares a particle with it comes first. In each
// round every rank
//   1. claims, for each particle it owns, that particle's first candidate
//      among those whose particles are all still free;
//   2. tells each neighbour, for every candidate shared with it (one
//      particle on each side), whether its own particle claimed it;
//   3. accepts every candidate that all its particles claimed;
//   4. tells each neighbour which of the shared candidates' particles are
//      now taken, and drops every candidate with a taken particle.
// A candidate claimed by all its particles comes first among the free
// candidates of each, so every earlier candidate of its particles was ruled
// out by an accepted one: the greedy pass accepts it too, and by induction
// every round accepts only what the greedy pass accepts and rules out only
// what it rules out. The first free candidate of all is claimed by all its
// particles, so each round accepts at least one and the rounds end (in
// practice after a few: chains of conflicts are short; where a round does
// not halve a rank's undecided candidates, as in a pile of overlapping
// disks, the rank then decides alone all that waits on no other rank, by
// the greedy pass over its own candidates). This is the
// lexicographically-first matching argument of Blelloch, Fineman and Shun
// (SPAA 2012), with the ranks' borders where their rounds exchange.
//
// A shared candidate is decided on both its ranks from the same two claims,
// so both decide alike. The class does no communication: its caller moves
// the bytes between the phases (MPI between ranks; the test, in one process).

#include "core/collision.hpp"
#include "particlesim/engine.hpp"
#include "stepped/step_pipeline.hpp"

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace particlesim {

// A rank's local index of each user index it holds (owned disks and
// ghosts), or no_collision for one it does not.
class LocalByUser {
public:
    explicit LocalByUser(std::span<const std::uint32_t> user_index);
    [[nodiscard]] std::uint32_t operator()(std::uint32_t user) const;

private:
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_user_;  // (user, local), sorted
};

// The greedy pass over candidates by user index, gathered from every rank
// (duplicates allowed), with the particles in `taken_users` taken already:
// the candidates it accepts.
std::vector<Collision> decide_in_order(std::vector<Collision> candidates, std::vector<std::uint32_t> taken_users);

class RankSelection {
public:
    // One step's selection. Local indices: the `owned_count` owned particles first, then
    // the ghosts; `user_index` gives every local particle's index in the
    // scene, `ghost_neighbour` each ghost's owner as a place in the caller's
    // list of neighbours (of `neighbours` places). `candidates`: every
    // candidate with at least one owned particle (walls only of owned
    // particles), in any order, duplicates allowed. Kept by reference until
    // the selection ends.
    // The accepted collisions' times go to `collision_time` (by local
    // particle, written only where one is accepted).
    void begin(std::span<const Collision> candidates, std::uint32_t owned_count,
               std::span<const std::uint32_t> user_index, std::span<const std::uint32_t> ghost_neighbour,
               std::size_t neighbours, std::span<double> collision_time);

    // Phase 1: each owned particle's first free candidate.
    void claim();
    // Phase 2: for each candidate shared with neighbour `n`, in the order
    // both sides agree on, 1 where this side's particle claimed it.
    void write_claims(std::size_t n, std::vector<std::uint8_t>& out) const;
    // Phase 3: accepts what all particles claimed; `claims[n]` is what
    // neighbour n wrote for this rank in phase 2.
    void accept(std::span<const std::vector<std::uint8_t>> claims);
    // Phase 4a: for each shared candidate, 1 where this side's particle is taken.
    void write_taken(std::size_t n, std::vector<std::uint8_t>& out) const;
    // Phase 4b: learns which ghosts are taken, drops what is ruled out;
    // returns how many candidates of this rank are still undecided (the
    // rounds go on while any rank has one).
    std::size_t end_round(std::span<const std::vector<std::uint8_t>> taken);

    // Where the rounds stall (each leaves more than half of what the one
    // before left: a pile of disks across a cut, whose shared pairs are
    // decided one a round), the ranks' undecided candidates go to one rank,
    // which decides them all by the greedy pass (decide_in_order()), and
    // every rank takes what was accepted.
    // This rank's undecided candidates, by user index (a pair's lower first).
    [[nodiscard]] std::vector<Collision> undecided_by_user() const;
    // Its particles taken that a shared candidate names, by user index: a
    // rank that decided alone in the last round took particles whose
    // shared candidates its neighbours still hold.
    [[nodiscard]] std::vector<std::uint32_t> taken_shared_by_user() const;
    // Takes, of `accepted` (by user index, as decide_in_order() returns
    // them), those with a particle of this rank, and ends the rounds.
    void take_accepted(std::span<const Collision> accepted);
    // The same before the first round, for collisions decided on one rank
    // that come before every candidate left (the pairs at t = 0 of disks
    // piled on one another: select_immediate_pairs()); the candidates they
    // rule out are dropped and the rounds decide the rest. Returns how many
    // candidates of this rank are left.
    std::size_t take_decided_first(std::span<const Collision> accepted);

    // After the rounds, by local particle: its partner's local index,
    // no_collision or wall_collision (a ghost's partner is set only when it
    // collides with an owned particle).
    // The caller may change the partners (the free flight sets them back).
    [[nodiscard]] std::span<std::uint32_t> partner() { return partner_; }
    [[nodiscard]] std::span<const std::uint32_t> partner() const { return partner_; }

    // The collisions accepted on this rank: walls of its particles, and each
    // pair once over all ranks (a shared pair on the rank of its lower user index).
    [[nodiscard]] const StepCounts& accepted() const { return accepted_; }
    // The number of shared candidates with neighbour n (the size of phase 2's and 4a's messages).
    [[nodiscard]] std::size_t shared_with(std::size_t n) const { return shared_[n].size(); }

private:
    // A candidate with one owned particle and one ghost.
    struct Shared {
        std::uint32_t candidate;
        std::uint32_t owned;
        std::uint32_t ghost;
        std::uint32_t user_low, user_high;  // the order both ranks list their shared candidates in
    };

    [[nodiscard]] bool owned(std::uint32_t local) const { return local < owned_; }
    [[nodiscard]] bool free(const Collision& c) const {
        return !taken_[c.i] && (c.kind == CollisionKind::wall || !taken_[c.j]);
    }
    void take(std::uint32_t local, std::uint32_t partner, double time);
    // Takes, of `accepted` (by user index), those with a particle of this rank.
    void take_of_this_rank(std::span<const Collision> accepted);
    // Decides what this rank can without its neighbours; returns how many
    // candidates stay undecided.
    std::size_t decide_alone();
    // Drops the undecided candidates with a taken particle, keeping the
    // others' order; returns how many are left.
    std::size_t drop_ruled_out();

    std::span<const Collision> candidates_;
    std::span<const std::uint32_t> user_index_;
    std::uint32_t owned_ = 0;
    std::vector<std::uint32_t> undecided_;          // candidates still undecided, ascending
    std::vector<std::uint32_t> earliest_;           // by owned particle: its claimed candidate
    std::vector<std::uint8_t> other_side_claimed_;  // by candidate
    std::vector<std::uint8_t> taken_;               // by local particle
    std::vector<std::uint8_t> waiting_;  // by local particle: decide_alone() met an undecided candidate of it
    std::vector<std::uint32_t> partner_;
    std::span<double> collision_time_;
    std::vector<std::vector<Shared>> shared_;  // by neighbour
    StepCounts accepted_;
};

}  // namespace particlesim
