#include "particlesim/overlap_counter.hpp"

#include <algorithm>
#include <cmath>

namespace particlesim {

std::uint64_t OverlapCounter::count(std::span<const Particle> particles, const SimParams& params) {
    const std::size_t n = particles.size();
    if (n < 2) return 0;
    // Cells at least a diameter wide, and no more of them than particles.
    const double by_diameter = std::floor(params.box_size / (2.0 * params.radius));
    const int side = static_cast<int>(std::max(1.0, std::min(by_diameter, std::floor(std::sqrt(static_cast<double>(n))))));
    const double cell_size = params.box_size / side;
    const auto column_of = [&](double x) { return std::clamp(static_cast<int>(x / cell_size), 0, side - 1); };

    // Counting sort of the particles by cell.
    const std::size_t cells = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    cell_start_.assign(cells + 1, 0);
    cell_of_.resize(n);
    by_cell_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2& p = particles[i].position;
        cell_of_[i] = static_cast<std::uint32_t>(column_of(p.y()) * side + column_of(p.x()));
        ++cell_start_[cell_of_[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
    for (std::size_t i = 0; i < n; ++i) by_cell_[cell_start_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
    for (std::size_t c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;

    const double diameter = 2.0 * params.radius;
    const double overlap_dist_sq = diameter * diameter * (1.0 - overlap_tolerance);
    std::uint64_t overlapping = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int column = static_cast<int>(cell_of_[i] % static_cast<std::uint32_t>(side));
        const int row = static_cast<int>(cell_of_[i] / static_cast<std::uint32_t>(side));
        bool found = false;
        for (int y = std::max(0, row - 1); y <= std::min(side - 1, row + 1) && !found; ++y) {
            for (int x = std::max(0, column - 1); x <= std::min(side - 1, column + 1) && !found; ++x) {
                const std::size_t cell = static_cast<std::size_t>(y) * static_cast<std::size_t>(side) + static_cast<std::size_t>(x);
                for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
                    const std::uint32_t j = by_cell_[k];
                    if (j != i && (particles[j].position - particles[i].position).squaredNorm() < overlap_dist_sq) {
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
