#pragma once
// A uniform grid refined where its points crowd: a grid sized by the count
// alone puts a row of touching disks, or a cluster in an empty box, into a
// few cells of hundreds, and every search there tests them all.

#include "core/uniform_grid.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace particlesim {

// The cells a side, from `side` doubled (up to `finest`) while a point's
// mean count of cell mates (the sum of each cell's count squared, over the
// count) passes `most_mates`. point_of(k) for k in [0, count): where point
// k is, in [0, extent]^2.
template <typename PointOf>
int refined_for_crowding(double extent, std::uint32_t count, PointOf&& point_of, int side, int finest,
                         double most_mates) {
    std::vector<std::uint32_t> counts;
    while (side < finest) {
        const UniformGrid grid(extent, side);
        counts.assign(grid.cell_count(), 0);
        for (std::uint32_t k = 0; k < count; ++k) ++counts[grid.cell_of(point_of(k))];
        double mates = 0.0;
        for (const std::uint32_t c : counts) mates += static_cast<double>(c) * static_cast<double>(c);
        if (mates <= most_mates * static_cast<double>(count)) break;
        side = std::min(2 * side, finest);
    }
    return side;
}

}  // namespace particlesim
