#include "stepped/immediate_selection.hpp"

#include "core/collision.hpp"
#include "core/physics.hpp"
#include "core/points_by_cell.hpp"
#include "core/uniform_grid.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <vector>

namespace particlesim {

std::uint64_t select_immediate_pairs(const PairSearchInput& in, std::span<const std::uint32_t> user_index,
                                     std::span<std::uint32_t> partner, std::span<double> collision_time) {
    // The places in the user's order (a rank's gathered disks hold some of
    // the user's indices only).
    std::vector<std::uint32_t> by_user(in.particles.size());
    std::iota(by_user.begin(), by_user.end(), 0U);
    if (!user_index.empty()) {
        std::sort(by_user.begin(), by_user.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return user_index[a] < user_index[b]; });
    }
    const auto undecided = [&](std::uint32_t place) {
        return std::atomic_ref<std::uint32_t>(partner[place]).load(std::memory_order_relaxed) == no_collision;
    };
    // The disks that may have a pair at t = 0, in the user's order: undecided,
    // and no wall at t = 0 (a pair's candidate comes before both wall times).
    std::vector<std::uint32_t> able;
    for (const std::uint32_t place : by_user) {
        if (undecided(place) && in.wall_time[place] > 0.0) able.push_back(place);
    }
    // Cells at least a contact distance wide (with UniformGrid's margin): a
    // pair at t = 0 has c <= 0, so its disks lie in neighbouring cells. Each
    // cell lists its disks in the user's order.
    const double contact = std::sqrt(in.box.contact_dist_sq);
    const double most_per_side = std::sqrt(static_cast<double>(able.size())) + 1.0;
    const UniformGrid grid(in.box.side, UniformGrid::cells_per_side(in.box.side, contact, most_per_side));
    const auto position_of = [&](std::uint32_t k) { return in.particles[able[k]].position; };
    const PointsByCell by_cell(grid, static_cast<std::uint32_t>(able.size()), position_of);

    const auto set_partner = [&](std::uint32_t place, std::uint32_t other) {
        std::atomic_ref<std::uint32_t>(partner[place]).store(other, std::memory_order_relaxed);
        collision_time[place] = 0.0;
    };
    std::uint64_t accepted = 0;
    const int last = grid.per_side() - 1;
    for (std::uint32_t k = 0; k < able.size(); ++k) {
        const std::uint32_t i = able[k];
        if (!undecided(i)) continue;
        const Particle& a = in.particles[i];
        const std::uint32_t cell = grid.cell_of(a.position);
        const int column = grid.column(cell);
        const int row = grid.row(cell);
        // The first able disk after k, in the user's order, across the 3 x 3 cells.
        std::uint32_t first = static_cast<std::uint32_t>(able.size());
        for (int y = std::max(row - 1, 0); y <= std::min(row + 1, last); ++y) {
            for (int x = std::max(column - 1, 0); x <= std::min(column + 1, last); ++x) {
                const std::span<const std::uint32_t> members = by_cell.in_cell(x, y);
                for (auto m = std::upper_bound(members.begin(), members.end(), k); m != members.end() && *m < first;
                     ++m) {
                    const std::uint32_t j = able[*m];
                    if (!undecided(j)) continue;
                    const Particle& b = in.particles[j];
                    if (contact_time(b.position - a.position, b.velocity - a.velocity, in.box.contact_dist_sq) == 0.0) {
                        first = *m;
                        break;
                    }
                }
            }
        }
        if (first == able.size()) continue;
        set_partner(i, able[first]);
        set_partner(able[first], i);
        ++accepted;
    }
    return accepted;
}

}  // namespace particlesim
