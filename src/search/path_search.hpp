#pragma once
// The paths search: a pair search for sparse scenes that keeps what it
// learns from one step to the next. A particle moves along one straight
// line between its collisions; while two particles keep their lines, the
// time interval in which they can be close is known once and for all. So
// only a particle that collided in the last micro-step gets its new line
// tested against every other line (PathLines, in float lanes); each pair
// that may come close is watched over its interval, and only watched pairs
// get the exact pair test of rules.md, in the micro-steps their interval
// covers.
//
// The candidates are exactly the brute force's: a candidate needs the two
// disks within 2r at some time of the micro-step, with both still on the
// lines (a collision first ends a line: pair_search.hpp). Free motion adds
// rounding to a line, at most 2^-51 L a micro-step and coordinate (a free
// particle stays in the box), so the watched distance is 2r plus 2^-36 L,
// and every line is made afresh at least every 1024 micro-steps.
//
// Its cost is (particles that collide) x (all particles) a micro-step, in
// float lanes, against the grid's cost per particle: it wins where few
// particles collide in a step (docs/benchmarks.md).

#include "search/pair_search.hpp"
#include "search/path_lines.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

class PathSearch {
public:
    // Appends the pair candidates of the micro-step starting at the state
    // `in` holds to out[0]; call once per micro-step, in order. New lines
    // are tested on up to out.size() threads. Returns false, appending
    // nothing and letting go of its watches, where it would watch more than
    // `watch_limit` pairs (stepped_tuning's paths_watches_*): another search
    // must take this micro-step and the rest of the run.
    [[nodiscard]] bool find_pairs(const PairSearchInput& in, std::span<ThreadCandidates> out, std::size_t watch_limit);

    // The stored particles were reordered: every line is made afresh.
    void forget() { lines_made_ = false; }

private:
    // A pair that may come within the watched distance between the micro-step
    // times `from` and `until`, while both keep the lines they had (serials).
    struct Watch {
        double from = 0.0;
        double until = 0.0;
        std::uint32_t i = 0;
        std::uint32_t j = 0;
        std::uint32_t serial_i = 0;
        std::uint32_t serial_j = 0;
    };

    // What one thread finds for the new lines it tests, on a cache line of its own.
    struct alignas(64) ThreadWatches {
        std::array<std::vector<std::uint32_t>, PathLines::max_block> near;  // a block's new lines
        std::vector<Watch> found;
    };
    // Lets go of every watch and line: the search is done with this run.
    void release();

    // Whether every line was made afresh.
    bool make_lines(const PairSearchInput& in);
    void watch_near(const PairSearchInput& in, std::size_t first, std::size_t count, double reach,
                    ThreadWatches& out) const;
    void watch_pairs(const PairSearchInput& in, std::uint32_t i, std::span<const std::uint32_t> near, double reach,
                     ThreadWatches& out) const;

    PathLines lines_;
    bool lines_made_ = false;
    std::int64_t micro_steps_ = 0;           // searched so far: the current time, in micro-steps
    std::int64_t lines_made_at_ = 0;         // when every line was last made afresh
    int steady_workers_ = 0;                 // threads of the last micro-step not made afresh; 0 before any
    std::vector<std::uint64_t> collisions_;  // by particle: its collision count when its line was made
    std::vector<std::uint32_t> serial_;      // by particle: counts its lines
    std::vector<std::uint8_t> new_line_;     // by particle: its line was made in this micro-step
    std::vector<std::uint32_t> new_lines_;   // those particles, in increasing order
    std::vector<Watch> watches_;
    std::vector<ThreadWatches> thread_watches_;
};

}  // namespace particlesim
