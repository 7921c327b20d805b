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

class UncertainStep {
public:
    explicit UncertainStep(const Box& box);

    // Finds every candidate the rules may produce from `before` in a step of
    // `duration`, and decides what it can of their selection.
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
