#pragma once
// The pair collisions at t = 0 decided without their candidates: where disks
// pile on one another, every approaching pair of the pile is a candidate at
// t = 0, k^2 / 2 of them for k disks, of which the greedy pass accepts at
// most k / 2. Past a budget the searches drop them (ImmediateCandidateBudget,
// pair_search.hpp) and this decides them from the particles instead, in
// memory linear in N.

#include "search/pair_search.hpp"

#include <cstdint>
#include <span>

namespace particlesim {

// rules.md "Select" for the pair candidates at t = 0, before every other
// candidate is decided: they come after the walls at t = 0 (whose disks
// have none: a pair's candidate must come before both wall times) and
// before everything later, and among themselves by the lowest user indices.
// So each undecided disk, in the user's order, takes the first undecided
// disk after it, in that order, that it touches or overlaps and approaches
// (contact_time() = 0, as the searches test it).
//
// `user_index`: the user's index of each place, all different (empty: the
// place's own; a rank's gathered disks hold some of the user's indices).
// Writes the partners (atomically, as the selection does: the searches read
// them) and collision time 0 of the accepted pairs; returns their count.
std::uint64_t select_immediate_pairs(const PairSearchInput& in, std::span<const std::uint32_t> user_index,
                                     std::span<std::uint32_t> partner, std::span<double> collision_time);

}  // namespace particlesim
