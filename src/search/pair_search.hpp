#pragma once
// What every pair search (brute force, grid, paths) receives and produces, and the one
// pair test they all apply, so that their candidate sets are identical.

#include "core/box.hpp"
#include "core/collision.hpp"
#include "core/physics.hpp"
#include "particlesim/particle.hpp"
#include "stepped/step_start.hpp"

#include <atomic>
#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

// The pair candidates at t = 0 (touching or overlapping disks that
// approach) that the searches keep in a step, shared by their threads. A
// pile of k overlapping disks makes up to k^2 / 2 of them; past `most` the
// searches drop the rest, and the selection decides every pair at t = 0
// itself, with memory linear in N (stepped/immediate_selection.hpp). Only
// pairs at t = 0 are dropped: they come before every later candidate in the
// rules' order, so the ones decided first leave the rest unchanged.
class ImmediateCandidateBudget {
public:
    // A new step's budget (one caller, while no search runs).
    void reset(std::size_t most) {
        most_ = most;
        kept_.store(0, std::memory_order_relaxed);
        overflowed_.store(false, std::memory_order_relaxed);
    }
    // Whether a search may keep one more candidate at t = 0.
    [[nodiscard]] bool keep() {
        if (overflowed_.load(std::memory_order_relaxed)) return false;
        if (kept_.fetch_add(1, std::memory_order_relaxed) < most_) return true;
        overflowed_.store(true, std::memory_order_relaxed);
        return false;
    }
    // Whether any candidate at t = 0 was dropped this step.
    [[nodiscard]] bool overflowed() const { return overflowed_.load(std::memory_order_relaxed); }

private:
    std::size_t most_ = static_cast<std::size_t>(-1);
    std::atomic<std::size_t> kept_{0};
    std::atomic<bool> overflowed_{false};
};

struct PairSearchInput {
    std::span<const Particle> particles;
    // First wall time of each particle from the start of the step (`never`
    // without one). A pair candidate at or after either particle's wall time
    // can never be selected: that particle's wall candidate comes first in
    // the order and marks it. Every search drops those candidates alike.
    std::span<const double> wall_time;
    Box box;
    double duration = 1.0;  // of the (micro-)step
    // The blocks' motion, when measured already (step_start.hpp); empty:
    // a search that needs it measures it.
    std::span<const BlockStart> blocks = {};
    // The area the particles spread over, when it is a part of the box (a
    // rank's strip); 0: the whole box. The grid sizes its cells by the
    // particles' spacing in it.
    double area = 0.0;
    // Where the candidates at t = 0 are counted against a budget; null:
    // every one is kept (simcheck's search of the pairs that may collide).
    ImmediateCandidateBudget* immediate = nullptr;
};

// Candidates found by one thread, on a cache line of its own.
struct alignas(64) ThreadCandidates {
    std::vector<Collision> found;
    std::uint64_t pair_tests = 0;
    // The most bytes the list may take; 0: most_candidate_bytes().
    std::size_t most_bytes = 0;

    // Appends c, the list growing within what the machine can hold: a pile
    // of k overlapping disks makes up to k^2 / 2 candidates a step where no
    // ImmediateCandidateBudget drops them (simcheck's search), and a list
    // past `most_bytes` (by default an eighth of the machine's memory)
    // throws std::bad_alloc (simcli: "out of memory while running") before
    // the kernel's out-of-memory killer would end the process without a
    // word.
    void add(const Collision& c) {
        if (found.size() == found.capacity()) [[unlikely]]
            grow();
        found.push_back(c);
    }
    // Twice the room (at least 1024 candidates) within the limit, or
    // std::bad_alloc where the list holds that much already.
    void grow();
    // An eighth of the machine's memory, read once.
    static std::size_t most_candidate_bytes();
};

// A selection a search may run between its time slices (the grid's). Once
// every candidate before `time` has been found, the collisions before it are
// decided: in the rules' greedy order a candidate's fate depends only on the
// candidates before it. Every candidate not found yet for a decided particle
// comes later and is ruled out, so the slices after leave its path out.
class SliceDecisions {
public:
    // Takes the candidates in `found` (leaving them empty) and decides every
    // collision before `time`, on up to `threads` threads (1 when called from
    // a thread that searches beside others). One call at a time.
    virtual void decide_before(double time, std::span<ThreadCandidates> found, int threads) = 0;

    // Decides every pair collision at t = 0 now, from the particles, before
    // any candidate is decided (they come first in the order): a search
    // whose first slice crowds many disks into a few cells (disks piled on
    // one another) calls it, then leaves the decided particles out. A
    // selection that cannot leaves it undone; the search is exact either way.
    virtual void decide_pairs_at_zero() {}

    // Whether particle i's collision is decided. Threads that search read it
    // while another decides: an atomic read, as the decisions write it.
    [[nodiscard]] bool decided(std::uint32_t i) const {
        return std::atomic_ref<std::uint32_t>(partner_[i]).load(std::memory_order_relaxed) != no_collision;
    }

protected:
    // `partner`: by particle, no_collision until its collision is decided.
    explicit SliceDecisions(std::span<std::uint32_t> partner) : partner_(partner) {}
    SliceDecisions(const SliceDecisions&) = default;
    SliceDecisions& operator=(const SliceDecisions&) = default;
    ~SliceDecisions() = default;

    std::span<std::uint32_t> partner_;  // what the decisions write
};

// What the pair test reads of one particle's motion; searches may keep
// copies of it in an order of their own (the grid keeps them in cell order,
// for locality). 32 bytes, aligned: a copy never straddles two cache lines.
struct alignas(32) PairTestState {
    Vec2 position;
    Vec2 velocity;
};

inline PairTestState pair_test_state(const PairSearchInput& in, std::uint32_t i) {
    return {in.particles[i].position, in.particles[i].velocity};
}

// The pair rule of rules.md plus the wall-time pruning above; appends the
// candidate of particles i < j (states a and b), if any, to `out`. The
// wall times are read only for a contact within the step: few pairs tested
// have one.
inline void test_pair(const PairTestState& a, const PairTestState& b, std::uint32_t i, std::uint32_t j,
                      const PairSearchInput& in, ThreadCandidates& out) {
    ++out.pair_tests;
    const double t = contact_time(b.position - a.position, b.velocity - a.velocity, in.box.contact_dist_sq);
    if (t <= in.duration && t < in.wall_time[i] && t < in.wall_time[j]) {
        if (t == 0.0 && in.immediate != nullptr && !in.immediate->keep()) return;
        out.add(Collision::pair(t, i, j));
    }
}

inline void test_pair(const PairSearchInput& in, std::uint32_t i, std::uint32_t j, ThreadCandidates& out) {
    test_pair(pair_test_state(in, i), pair_test_state(in, j), i, j, in, out);
}

}  // namespace particlesim
