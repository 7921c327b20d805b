#pragma once
// The selection (rules.md "Select") run in stages while the grid search
// works through its time slices: each stage decides the collisions before a
// time that every candidate before it has been found by, and the decided
// particles drop out of the slices after (SliceDecisions, pair_search.hpp).
// The same collisions as one selection after the search: a candidate's fate
// depends only on the candidates before it in the order, and a candidate
// that shares a particle with a decided collision is ruled out by it.

#include "core/collision.hpp"
#include "particlesim/engine.hpp"
#include "search/pair_search.hpp"
#include "stepped/step_pipeline.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

class EarlySelection final : public SliceDecisions {
public:
    // `candidates` holds the step's wall candidates; `ready` is a buffer
    // kept between steps. `collision_time` is the array the search reads as
    // its wall times: a decided particle's entry becomes its collision's
    // time, which is no later than its wall time.
    EarlySelection(std::vector<Collision>& candidates, std::vector<Collision>& ready, const CandidateOrder& order,
                   std::span<std::uint32_t> partner, std::span<double> collision_time, SelectionScratch& scratch,
                   int threads)
        : candidates_(candidates),
          ready_(ready),
          order_(order),
          partner_(partner),
          collision_time_(collision_time),
          scratch_(scratch),
          threads_(threads) {}

    void decide_before(double time, std::span<ThreadCandidates> found) override;

    // Decides every collision left, with what the search found since the
    // last stage; returns the step's accepted collisions.
    StepCounts decide_rest(std::span<ThreadCandidates> found);

private:
    // Moves the undecided candidates before `time` (of those kept and those
    // in `found`) into ready_, and keeps the undecided later ones.
    void gather_ready(double time, std::span<ThreadCandidates> found);

    std::vector<Collision>& candidates_;  // undecided, possibly later than the stages so far
    std::vector<Collision>& ready_;
    const CandidateOrder& order_;
    std::span<std::uint32_t> partner_;
    std::span<double> collision_time_;
    SelectionScratch& scratch_;
    int threads_;
    bool decided_any_ = false;
    StepCounts accepted_;
};

}  // namespace particlesim
