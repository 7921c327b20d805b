#pragma once
// A uniform grid over the paths search's lines, so that a new line is tested
// only against the lines that come near it in space instead of all of them.
// Each line is kept as the segment its particle can still run along it: from
// its position now to where it reaches a wall (rounded up to the end of that
// micro-step, and one more): its line ends there, since a wall candidate
// within a step is always taken unless a pair collision, which also ends the
// line, comes first (rules.md). Two lines can only meet while both last, at
// a time when each particle is on its segment; so a segment is registered in
// every cell within twice the watched distance of it, and a query scans the
// cells its own segment crosses: every line that may meet it is there.
//
// Each cell keeps copies of its lines in the float layout of PathLines,
// padded with lines that never pass, so the same lane test runs over a cell
// as over all lines. A query finds the same lines as PathLines::gather_near()
// among those that can meet it in time, and no other pair test is lost: a
// pair whose meeting lies beyond either segment is never tested by the
// search, whose watch ends with the line (path_search.hpp).
//
// The grid is remade every micro-step from the particles' positions: its cost
// is a rasterization and a counting sort of (lines x cells per segment).

#include "core/uniform_grid.hpp"
#include "search/path_lines.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

struct LineSegment {
    Vec2 from, to;
};

class LineCells {
public:
    // Remakes the grid: `per_side` x `per_side` cells over the box of side
    // `box_side`, line i of `lines` registered along segments[i] widened by
    // `widen` (plus a margin for rounding).
    void build(const PathLines& lines, std::span<const LineSegment> segments, double box_side, int per_side,
               double widen);

    // Appends to `near`, in increasing order, every line j != i registered in
    // a cell that i's segment crosses and whose line passes the lane test of
    // i's line within `reach`.
    void gather_near(const PathLines& lines, std::uint32_t i, const LineSegment& segment, double reach,
                     std::vector<std::uint32_t>& near) const;

    // Lines registered, counting each cell a line is in (padding included).
    [[nodiscard]] std::size_t entries() const { return ids_.size(); }
    [[nodiscard]] const UniformGrid& grid() const { return grid_; }

private:
    UniformGrid grid_;
    double margin_ = 0.0;
    std::vector<std::uint32_t> cell_start_;  // per cell, and one past the last
    std::vector<std::uint32_t> ids_;         // by place: the line's particle
    std::vector<float> x_, y_, vx_, vy_;     // by place: copies of the lines
    // Scratch of build(): each registration's cell and line, each cell's next place.
    std::vector<std::uint32_t> entry_cell_, entry_line_, fill_;
};

}  // namespace particlesim
