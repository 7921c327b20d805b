#include "measure/overlap_counter.hpp"

#include "core/box.hpp"
#include "core/physics.hpp"
#include "core/uniform_grid.hpp"

#include <algorithm>
#include <cmath>

namespace particlesim {

std::uint64_t OverlapCounter::count(std::span<const Particle> particles, const World& world) {
    const std::size_t n = particles.size();
    if (n < 2) return 0;
    // Cells at least a diameter wide, and no more of them than particles.
    const UniformGrid grid(world.box_size, UniformGrid::cells_per_side(world.box_size, 2.0 * world.radius,
                                                                       std::sqrt(static_cast<double>(n))));
    const int side = grid.per_side();
    const double contact_dist_sq = Box::of(world).contact_dist_sq;

    // Counting sort of the particles by cell.
    const std::size_t cells = grid.cell_count();
    cell_start_.assign(cells + 1, 0);
    cell_of_.resize(n);
    by_cell_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        cell_of_[i] = grid.cell_of(particles[i].position);
        ++cell_start_[cell_of_[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
    for (std::size_t i = 0; i < n; ++i) by_cell_[cell_start_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
    for (std::size_t c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;

    std::uint64_t overlapping = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int column = grid.column(cell_of_[i]);
        const int row = grid.row(cell_of_[i]);
        bool found = false;
        for (int y = std::max(0, row - 1); y <= std::min(side - 1, row + 1) && !found; ++y) {
            for (int x = std::max(0, column - 1); x <= std::min(side - 1, column + 1) && !found; ++x) {
                const std::size_t cell =
                    static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x);
                for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
                    const std::uint32_t j = by_cell_[k];
                    if (j != i && disks_overlap(particles[j].position - particles[i].position, contact_dist_sq)) {
                        found = true;
                        break;
                    }
                }
            }
        }
        if (found) ++overlapping;
    }
    return overlapping;
}

}  // namespace particlesim
