#pragma once
// Every pair of points closer than `reach`, found through a uniform grid of
// cells at least `reach` wide: the checker's candidate pairs at the start of
// a step, and the overlaps it looks for in a printed state.

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
    const std::size_t count = points.size();
    const UniformGrid grid(extent,
                           UniformGrid::cells_per_side(extent, reach, std::sqrt(static_cast<double>(count)) + 1.0));
    std::vector<std::uint32_t> cell_start(grid.cell_count() + 1, 0);
    std::vector<std::uint32_t> in_cell(count);
    for (const Vec2& p : points) ++cell_start[grid.cell_of(p) + 1];
    for (std::size_t c = 0; c < grid.cell_count(); ++c) cell_start[c + 1] += cell_start[c];
    std::vector<std::uint32_t> fill(cell_start.begin(), cell_start.end() - 1);
    for (std::uint32_t p = 0; p < count; ++p) in_cell[fill[grid.cell_of(points[p])]++] = p;
    const double reach_sq = reach * reach;
    for (std::uint32_t p = 0; p < count; ++p) {
        const int column = grid.column_of(points[p].x());
        const int row = grid.column_of(points[p].y());
        for (int r = std::max(row - 1, 0); r <= std::min(row + 1, grid.per_side() - 1); ++r) {
            for (int c = std::max(column - 1, 0); c <= std::min(column + 1, grid.per_side() - 1); ++c) {
                const std::uint32_t cell = grid.cell_at(c, r);
                for (std::uint32_t k = cell_start[cell]; k < cell_start[cell + 1]; ++k) {
                    const std::uint32_t q = in_cell[k];
                    if (q > p && (points[q] - points[p]).squaredNorm() <= reach_sq) visit(p, q);
                }
            }
        }
    }
}

}  // namespace particlesim
