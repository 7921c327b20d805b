#pragma once
// The reference pair search: every pair i < j. Slow, obviously right, kept
// forever behind `--broadphase brute` to check every faster search against.

#include "search/pair_search.hpp"

#include <span>

namespace particlesim {

// Fills one ThreadCandidates per worker thread (`buffers.size()` threads).
void find_pairs_brute_force(const PairSearchInput& in, std::span<ThreadCandidates> buffers);

}  // namespace particlesim
