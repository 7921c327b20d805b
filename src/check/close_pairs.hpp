#pragma once
// Every pair of points closer than `reach`, found through a uniform grid of
// cells at least `reach` wide: the checker's candidate pairs at the start of
// a step, and the overlaps it looks for in a printed state.

#include "core/points_by_cell.hpp"
#include "core/uniform_grid.hpp"
#include "particlesim/particle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

// Calls `visit(i, j)` (i < j) for every pair of `points` in [0, extent]^2
// whose distance is at most `reach`.
template <typename Visit>
void for_each_close_pair(std::span<const Vec2> points, double extent, double reach, Visit visit) {
    const auto count = static_cast<std::uint32_t>(points.size());
    const UniformGrid grid(extent,
                           UniformGrid::cells_per_side(extent, reach, std::sqrt(static_cast<double>(count)) + 1.0));
    const PointsByCell by_cell(grid, count, [&](std::uint32_t k) { return points[k]; });
    const double reach_sq = reach * reach;
    for (std::uint32_t p = 0; p < count; ++p) {
        const int column = grid.column_of(points[p].x());
        const int row = grid.column_of(points[p].y());
        for (int r = std::max(row - 1, 0); r <= std::min(row + 1, grid.per_side() - 1); ++r) {
            for (int c = std::max(column - 1, 0); c <= std::min(column + 1, grid.per_side() - 1); ++c) {
                by_cell.for_each_in(c, r, [&](std::uint32_t q) {
                    if (q > p && (points[q] - points[p]).squaredNorm() <= reach_sq) visit(p, q);
                });
            }
        }
    }
}

}  // namespace particlesim
