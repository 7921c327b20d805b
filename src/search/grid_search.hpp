#pragma once
// The fast pair search: exact for any speeds. It never assumes a speed limit:
// the step is cut into time slices, and in each slice every particle's swept
// box (its path in that slice, widened by r and a rounding margin) is binned
// by its lower corner into a uniform grid (a counting sort, with the boxes
// kept as float boxes in cell order). Two boxes that fit a cell can only
// overlap when their cells are neighbours, so a half stencil of contiguous
// ranges finds each such pair once, four boxes per comparison. A path too
// long for a cell is cut into pieces in time; one too long even for that is
// a large box, scanned against the cells it covers and against every other
// large box. Where the cells hold several boxes each (long paths), the scan
// also tests the particles' lines in the same lanes (line_test.hpp), which
// rules out most overlapping boxes of particles that pass far apart. Every
// pair that passes gets the shared pair test, a superset of the pairs that
// can collide, so the result is exactly the brute-force candidate set.

#include "core/uniform_grid.hpp"
#include "search/float_bounds_array.hpp"
#include "search/line_test.hpp"
#include "search/pair_search.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace particlesim {

// The shape of the search in one step; chosen per step from the scene.
struct GridLayout {
    UniformGrid grid;
    int slices = 1;
    // The pair collisions a particle may expect in the first slice (its mean
    // path there through the others' density, 4r wide): how much the first
    // slice's decisions leave out of the later ones.
    double first_slice_collisions = 0.0;
    double reach = 0.0;  // r plus the rounding margin added around each path
    // 1, or for a box far from 1 the power of two that brings L into [1, 2):
    // float bounds are taken of scaled coordinates, so they keep their
    // precision at every scale of the accepted range.
    double float_scale = 1.0;
    // The particles' lines in float for the scans of sparse slices (line_test.hpp):
    // powers of two that bring L and the fastest speed into [0.5, 1), and the test's terms.
    double line_position_scale = 1.0;
    double line_velocity_scale = 1.0;
    LineTerms line_terms{};
};

// The time slices a step is cut into: enough for a mean path of `mean_sweep`
// to cover about `slice_sweep` a slice, from 1 to stepped_tuning::max_slices.
[[nodiscard]] int time_slices(double mean_sweep, double slice_sweep);

// A particle's path within one time slice, widened by the layout's reach.
struct SweptBounds {
    double min_x, min_y, max_x, max_y;

    // Branch-free: in a grid most tested boxes miss, in no predictable pattern.
    [[nodiscard]] bool overlaps(const SweptBounds& other) const {
        return (min_x <= other.max_x) & (other.min_x <= max_x) & (min_y <= other.max_y) & (other.min_y <= max_y);
    }
};

class GridSearch {
public:
    // Scans `lanes` boxes at a time: 4 (any processor), 8 (x86-64 with AVX2)
    // or 16 (AVX-512); 0 picks the widest this processor has. All find the
    // same pairs.
    explicit GridSearch(int lanes = 0);
    [[nodiscard]] static bool supports_lanes(int lanes);
    ~GridSearch();
    GridSearch(GridSearch&&) noexcept;
    GridSearch& operator=(GridSearch&&) noexcept;

    // forced_cells imposes a G x G grid (still exact); without it the grid is
    // sized from the particles' motion in this step and r. With `decisions`,
    // the slices are searched in time order, and as they are searched the
    // collisions before them are decided, so that the slices after leave
    // out the particles already decided (the same collisions for the
    // selection, fewer paths to bin and test). Candidates the decisions
    // did not take are left in `buffers`. Where the first slice crowds its
    // cells with disks meeting at t = 0 (a pile), `pairs_at_zero` (by
    // default `decisions`) is asked to decide those pairs first
    // (SliceDecisions::decide_pairs_at_zero()), and the slice is binned again
    // without their disks.
    void find_pairs(const PairSearchInput& in, std::optional<int> forced_cells, std::span<ThreadCandidates> buffers,
                    SliceDecisions* decisions = nullptr, SliceDecisions* pairs_at_zero = nullptr);

    // Per-slice buffers; one per thread when slices run in parallel.
    struct SliceWorkspace;  // defined in grid_search.cpp

private:
    // Inline: it runs once per particle and slice.
    [[nodiscard]] SweptBounds swept_bounds(const Particle& particle, double begin, double end) const {
        const Vec2 from = particle.position + particle.velocity * begin;
        const Vec2 to = particle.position + particle.velocity * end;
        const double reach = layout_.reach;
        return {std::min(from.x(), to.x()) - reach, std::min(from.y(), to.y()) - reach,
                std::max(from.x(), to.x()) + reach, std::max(from.y(), to.y()) + reach};
    }
    // Piece `piece` of `pieces` equal parts in time of the path from `begin` to `end`.
    [[nodiscard]] SweptBounds piece_bounds(const Particle& particle, double begin, double end, int piece,
                                           int pieces) const {
        const double span = end - begin;
        const double piece_begin = begin + span * piece / pieces;
        const double piece_end = piece + 1 == pieces ? end : begin + span * (piece + 1) / pieces;
        return swept_bounds(particle, piece_begin, piece_end);
    }
    // A particle's line in float, scaled as the layout says. Inline: it runs once per binned box.
    [[nodiscard]] FloatLine float_line(const Particle& particle) const {
        const double position_scale = layout_.line_position_scale;
        const double velocity_scale = layout_.line_velocity_scale;
        return {static_cast<float>(particle.position.x() * position_scale),
                static_cast<float>(particle.position.y() * position_scale),
                static_cast<float>(particle.velocity.x() * velocity_scale),
                static_cast<float>(particle.velocity.y() * velocity_scale)};
    }
    // How many pieces a path must be cut into for each to fit a cell; 0 when
    // too many.
    [[nodiscard]] int pieces_to_fit(const Particle& particle, double begin, double end, double fit) const;
    GridLayout choose_layout(const PairSearchInput& in, std::optional<int> forced_cells, int threads);
    void process_slice(const PairSearchInput& in, int slice, SliceWorkspace& ws, std::span<ThreadCandidates> out,
                       int threads, const SliceDecisions* decisions) const;
    // Whether the slice just binned in `ws` crowds so many boxes into its
    // cells, meeting at t = 0, that the pairs at t = 0 are better decided
    // before its scan.
    [[nodiscard]] bool crowded(const PairSearchInput& in, const SliceWorkspace& ws) const;
    [[nodiscard]] double decided_before(const PairSearchInput& in, int searched) const;
    void search_slices_deciding(const PairSearchInput& in, std::span<ThreadCandidates> buffers,
                                SliceDecisions& decisions);
    void prepare(SliceWorkspace& ws, std::size_t count, int workers) const;
    // Binning a slice: a counting sort of the paths' boxes by cell, in four steps.
    struct Binning;  // what the steps share; defined in grid_search.cpp
    void bin_slice(const PairSearchInput& in, int slice, SliceWorkspace& ws, int threads,
                   const SliceDecisions* decisions) const;
    std::size_t count_boxes(const Binning& binning, bool cut_into_pieces) const;
    void sum_cell_places(const Binning& binning) const;
    void place_boxes(const Binning& binning) const;
    void close_cell_starts(const Binning& binning) const;
    // The lowest bounds of each cell's boxes, which let the scans leave out
    // the neighbours a box cannot reach.
    void find_cell_lowest(const Binning& binning) const;
    void test_small_pairs(const PairSearchInput& in, const SliceWorkspace& ws, std::span<ThreadCandidates> out,
                          int threads) const;
    void test_large_pairs(const PairSearchInput& in, const SliceWorkspace& ws, std::span<ThreadCandidates> out,
                          int threads) const;

    int lanes_ = 4;
    GridLayout layout_;
    // The step's decisions, also where its slices run no stages: the first
    // slice may ask them to decide the pairs at t = 0 (crowded()).
    SliceDecisions* pairs_at_zero_ = nullptr;
    std::vector<BlockStart> block_starts_;  // when the step brings none
    std::vector<SliceWorkspace> workspaces_;
    // Where threads take whole slices and decisions run: each slice's
    // candidates, and whether it is searched.
    std::vector<ThreadCandidates> slice_found_;
    std::vector<std::uint8_t> slice_searched_;
};

}  // namespace particlesim
