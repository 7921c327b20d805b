#include "stepped/early_selection.hpp"

#include <limits>

namespace particlesim {

void EarlySelection::gather_ready(double time, std::span<ThreadCandidates> found) {
    ready_.clear();
    // Kept in place: the later ones close up at the front of candidates_.
    auto kept_end = candidates_.begin();
    const auto sort_out = [&](const Collision& c, bool kept) {
        if (!undecided(c, partner_)) return;
        if (c.time < time) {
            ready_.push_back(c);
        } else if (kept) {
            *kept_end++ = c;
        } else {
            candidates_.push_back(c);
        }
    };
    for (const Collision& c : candidates_) sort_out(c, true);
    candidates_.erase(kept_end, candidates_.end());
    for (ThreadCandidates& thread : found) {
        for (const Collision& c : thread.found) sort_out(c, false);
        thread.found.clear();
    }
}

void EarlySelection::make_stage_times() {
    if (stage_time_.size() < partner_.size()) stage_time_.resize(partner_.size());
}

// Before any other decision: every candidate at t = 0 has been found by
// then (the first slice holds them), and they come first in the order.
void EarlySelection::decide_immediate_pairs() {
    if (input_.immediate != nullptr && input_.immediate->overflowed()) decide_pairs_at_zero();
}

// Once, before any other decision. What the search kept or keeps finding of
// the pairs at t = 0 is ruled out by the pairs decided here.
void EarlySelection::decide_pairs_at_zero() {
    if (immediate_decided_) return;
    immediate_decided_ = true;
    make_stage_times();
    accepted_.particle_collisions += select_immediate_pairs(input_, order_.user_index(), partner_, stage_time_);
    decided_any_ = true;
}

void EarlySelection::decide_before(double time, std::span<ThreadCandidates> found, int threads) {
    decide_immediate_pairs();
    gather_ready(time, found);
    if (ready_.empty()) return;
    make_stage_times();
    // Every candidate before `time` is in ready_, and none shares a particle
    // with a collision decided before: the rounds decide them as the greedy
    // pass over all candidates would.
    accepted_ += select_collisions(ready_, {}, order_, partner_, stage_time_, scratch_, threads);
    decided_any_ = true;
}

StepCounts EarlySelection::decide_rest(std::span<ThreadCandidates> found) {
    decide_immediate_pairs();
    if (!decided_any_) {  // no stage ran: the one selection of every candidate
        return select_collisions(candidates_, found, order_, partner_, collision_time_, scratch_, threads_);
    }
    decide_before(std::numeric_limits<double>::infinity(), found, threads_);
    for (std::size_t i = 0; i < partner_.size(); ++i) {
        if (partner_[i] != no_collision) collision_time_[i] = stage_time_[i];
    }
    return accepted_;
}

}  // namespace particlesim
