#pragma once
// One (micro-)step of the step rules on states known only within bounds (a
// printed state, or one propagated from it). Every decision of the rules
// (a candidate exists, which comes first, a particle stops at a wall) is
// three-valued: decided, or within rounding and so allowed either way. What
// it yields per particle is the set of fates the rules allow (no collision,
// or one of its candidates) and the bounds of the state each fate leads to.
// The step checker (step_check.cpp) matches printed states against them.

#include "check/uncertain.hpp"
#include "core/box.hpp"
#include "core/collision.hpp"
#include "particlesim/particle.hpp"
#include "search/grid_search.hpp"

#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace particlesim {

struct UncertainParticle {
    Uncertain x, y, vx, vy;
};

UncertainParticle uncertain_particle(const Particle& particle, double uncertainty);
// Componentwise: bounds holding both.
UncertainParticle hull(const UncertainParticle& a, const UncertainParticle& b);
Particle midpoint(const UncertainParticle& particle);

// A collision the rules may accept, with its existence, its time and (for a
// wall) which axes hit, as far as they are decided.
struct PossibleCollision {
    Uncertain time;
    CollisionKind kind = CollisionKind::wall;
    std::uint32_t i = 0;
    std::uint32_t j = 0;        // the other particle of a pair
    Tri exists = Tri::no;       // a candidate at all (time within the step, ...)
    Tri touching = Tri::no;     // a pair touching or overlapping at the start
    Tri approaching = Tri::no;  // a pair moving towards each other (B < 0)
    Tri on_x = Tri::no;         // a wall reached on x at `time` (both: a corner)
    Tri on_y = Tri::no;
    Tri accepted = Tri::no;  // selected by the greedy walk in (t, kind, i, j) order

    [[nodiscard]] std::uint32_t other(std::uint32_t particle) const { return particle == i ? j : i; }
};

// What one particle may do in the step: no collision (candidate < 0), or a
// candidate of its own; and the bounds of its state at the end of the step.
struct Fate {
    int candidate = -1;
    UncertainParticle outcome;
};

// Thrown by UncertainStep::predict() where more pairs may collide in the
// step than the checker holds: disks piled on one another make every pair
// of the pile one, k^2 / 2 for k disks.
class TooManyPossiblePairs : public std::runtime_error {
public:
    explicit TooManyPossiblePairs(std::size_t most);
};

// What one pair that may collide takes while a step is judged (its key, its
// candidate, its places in the particles' lists and in the order): simcheck
// on a pile of 5000 disks, 12.5 M pairs, peaked at 793 MB.
inline constexpr std::size_t bytes_per_possible_pair = 64;

class UncertainStep {
public:
    // `most_pairs`: the most pairs that may collide in a step it holds (0:
    // an eighth of the machine's memory's worth).
    explicit UncertainStep(const Box& box, std::size_t most_pairs = 0);

    // Finds every candidate the rules may produce from `before` in a step of
    // `duration`, and decides what it can of their selection. Throws
    // TooManyPossiblePairs past its most pairs.
    void predict(std::span<const UncertainParticle> before, double duration);

    [[nodiscard]] const std::vector<PossibleCollision>& candidates() const { return candidates_; }
    // The candidates of a particle that are not certainly rejected.
    [[nodiscard]] std::span<const std::uint32_t> candidates_of(std::uint32_t particle) const;
    // Every fate the rules allow the particle, each with its outcome.
    void fates_of(std::uint32_t particle, std::vector<Fate>& out) const;
    // The outcome of a given fate, also one the rules forbid (for reports).
    [[nodiscard]] UncertainParticle outcome(std::uint32_t particle, int candidate) const;
    [[nodiscard]] bool may_be_free(std::uint32_t particle) const;

private:
    void find_candidate_pairs(std::span<const UncertainParticle> before);
    void add_pair(std::uint32_t i, std::uint32_t j);
    void select();
    [[nodiscard]] Tri comes_before(const PossibleCollision& a, const PossibleCollision& b) const;

    Box box_;
    std::size_t most_pairs_;
    double duration_ = 1.0;
    std::span<const UncertainParticle> before_;
    std::vector<PossibleCollision> candidates_;
    std::vector<std::uint32_t> offsets_;  // candidates_of(p) = listed_[offsets_[p] .. offsets_[p + 1])
    std::vector<std::uint32_t> listed_;
    GridSearch search_;
    std::vector<ThreadCandidates> found_;  // one per thread of the pair search
    std::vector<Particle> midpoints_;
    std::vector<Vec2> positions_;
    std::vector<double> no_wall_;
    std::vector<std::uint64_t> pair_keys_;
};

}  // namespace particlesim
