#pragma once
// The selection (rules.md "Select") run in stages while the grid search
// works through its time slices: each stage decides the collisions before a
// time by which every candidate has been found, and the decided particles
// drop out of the slices after (SliceDecisions, pair_search.hpp). The same
// collisions as one selection after the search: a candidate's fate depends
// only on the candidates before it in the order, and a candidate that shares
// a particle with a decided collision is ruled out by it.

#include "core/collision.hpp"
#include "particlesim/engine.hpp"
#include "search/pair_search.hpp"
#include "stepped/immediate_selection.hpp"
#include "stepped/step_pipeline.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

class EarlySelection final : public SliceDecisions {
public:
    // `input` is the search's: where it dropped candidates at t = 0
    // (ImmediateCandidateBudget), the first decision decides those pairs
    // from its particles (immediate_selection.hpp).
    // `candidates` holds the step's wall candidates. `collision_time` gets
    // the accepted collisions' times once the search is over: it is the
    // array the search reads its wall times from. `ready` and `stage_time`
    // are buffers kept between steps (stage_time grows to the particles on
    // the first stage).
    EarlySelection(const PairSearchInput& input, std::vector<Collision>& candidates, std::vector<Collision>& ready,
                   const CandidateOrder& order, std::span<std::uint32_t> partner, std::span<double> collision_time,
                   std::vector<double>& stage_time, SelectionScratch& scratch, int threads)
        : SliceDecisions(partner),
          input_(input),
          candidates_(candidates),
          ready_(ready),
          order_(order),
          collision_time_(collision_time),
          stage_time_(stage_time),
          scratch_(scratch),
          threads_(threads) {}

    void decide_before(double time, std::span<ThreadCandidates> found, int threads) override;
    void decide_pairs_at_zero() override;

    // Decides every collision left, with what the search left in `found`;
    // returns the step's accepted collisions.
    StepCounts decide_rest(std::span<ThreadCandidates> found);

private:
    // Moves the undecided candidates before `time` (of those kept and those
    // in `found`) into ready_, and keeps the undecided later ones.
    void gather_ready(double time, std::span<ThreadCandidates> found);
    // The pairs at t = 0 (decide_pairs_at_zero()) if the search dropped
    // some of their candidates.
    void decide_immediate_pairs();
    // stage_time_ grown to the particles.
    void make_stage_times();

    const PairSearchInput& input_;
    std::vector<Collision>& candidates_;  // undecided, possibly later than the stages so far
    std::vector<Collision>& ready_;
    const CandidateOrder& order_;
    std::span<double> collision_time_;
    // The stages' collision times, while the search still reads collision_time_ as wall times.
    std::vector<double>& stage_time_;
    SelectionScratch& scratch_;
    int threads_;
    bool decided_any_ = false;
    bool immediate_decided_ = false;
    StepCounts accepted_;
};

}  // namespace particlesim
