#pragma once
// What every pair search (brute force, grid) receives and produces, and the one
// pair test they all apply, so that their candidate sets are identical.

#include "particlesim/box.hpp"
#include "particlesim/collision.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/physics.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

struct PairSearchInput {
    std::span<const Particle> particles;
    // First wall time of each particle from the start of the step (`never`
    // without one). A pair candidate at or after either particle's wall time
    // can never be selected: that particle's wall candidate comes first in
    // the order and marks it. Every search drops those candidates alike.
    std::span<const double> wall_time;
    Box box;
    double duration = 1.0;  // of the (micro-)step
};

// Candidates found by one thread, on a cache line of its own.
struct alignas(64) ThreadCandidates {
    std::vector<Collision> found;
    std::uint64_t pair_tests = 0;
};

// The pair rule of rules.md plus the wall-time pruning above; appends the
// candidate of i < j, if any, to `out`.
inline void test_pair(const PairSearchInput& in, std::uint32_t i, std::uint32_t j, ThreadCandidates& out) {
    ++out.pair_tests;
    const Particle& a = in.particles[i];
    const Particle& b = in.particles[j];
    const double t = contact_time(b.position - a.position, b.velocity - a.velocity, in.box.contact_dist_sq);
    if (t <= in.duration && t < in.wall_time[i] && t < in.wall_time[j]) out.found.push_back(Collision::pair(t, i, j));
}

}  // namespace particlesim
