#pragma once
// Every pair of points closer than `reach`, found through a uniform grid of
// cells at least `reach` wide: the checker's candidate pairs at the start of
// a step, and the overlaps it looks for in a printed state.

#include "core/physics.hpp"
#include "core/points_by_cell.hpp"
#include "core/uniform_grid.hpp"
#include "particlesim/particle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

// Where the points lie: a walled square, or a periodic one, whose opposite
// sides are the same place.
enum class CloseIn { square, periodic_square };

// The separation from a to b; in a periodic square of side `extent`, to the
// image of b nearest a.
inline Vec2 separation_in(CloseIn space, double extent, const Vec2& a, const Vec2& b) {
    Vec2 d = b - a;
    if (space == CloseIn::periodic_square) {
        for (int axis = 0; axis < 2; ++axis) d[axis] = nearest_image(d[axis], extent);
    }
    return d;
}

// Calls `visit(i, j)` (i < j) for every pair of `points` in [0, extent]^2
// whose distance (through the sides too, in a periodic square) is at most
// `reach`. Each pair is visited once.
template <typename Visit>
void for_each_close_pair(std::span<const Vec2> points, double extent, double reach, CloseIn space, Visit visit) {
    const auto count = static_cast<std::uint32_t>(points.size());
    const UniformGrid grid(extent,
                           UniformGrid::cells_per_side(extent, reach, std::sqrt(static_cast<double>(count)) + 1.0));
    const PointsByCell by_cell(grid, count, [&](std::uint32_t k) { return points[k]; });
    const double reach_sq = reach * reach;
    const int side = grid.per_side();
    const bool wraps = space == CloseIn::periodic_square;
    // The columns (or rows) next to `at`, each once: across the sides where
    // the square wraps, and all of them where it has fewer than 3.
    const auto neighbours = [&](int at, int(&out)[3]) {
        if (wraps && side < 3) {
            for (int k = 0; k < side; ++k) out[k] = k;
            return side;
        }
        int n = 0;
        for (int k = at - 1; k <= at + 1; ++k) {
            if (wraps)
                out[n++] = (k + side) % side;
            else if (k >= 0 && k < side)
                out[n++] = k;
        }
        return n;
    };
    for (std::uint32_t p = 0; p < count; ++p) {
        int rows[3], columns[3];
        const int row_count = neighbours(grid.column_of(points[p].y()), rows);
        const int column_count = neighbours(grid.column_of(points[p].x()), columns);
        for (int r = 0; r < row_count; ++r) {
            for (int c = 0; c < column_count; ++c) {
                by_cell.for_each_in(columns[c], rows[r], [&](std::uint32_t q) {
                    if (q > p && separation_in(space, extent, points[p], points[q]).squaredNorm() <= reach_sq)
                        visit(p, q);
                });
            }
        }
    }
}

}  // namespace particlesim
