#pragma once
// A uniform grid of cells, each a linked list of the particles in it (see
// bucket_lists.hpp), so that a particle moves between cells in O(1). Cells are at least a
// diameter wide: two disks in contact are in the same or adjacent cells.

#include "bucket_lists.hpp"
#include "uniform_grid.hpp"

#include <algorithm>
#include <cstdint>

namespace particlesim {

class CellList {
public:
    CellList(const UniformGrid& grid, std::size_t particle_count)
        : grid_(grid), members_(grid.cell_count(), particle_count) {}

    [[nodiscard]] const UniformGrid& grid() const { return grid_; }
    [[nodiscard]] std::uint32_t cell_of_particle(std::uint32_t particle) const { return members_.bucket_of(particle); }

    void insert(std::uint32_t particle, std::uint32_t cell) { members_.insert(particle, cell); }
    void move(std::uint32_t particle, std::uint32_t cell) { members_.move(particle, cell); }

    // visit(j) for every particle in the cell at (column, row), if it exists.
    template <typename Visit>
    void for_each_in(int column, int row, Visit&& visit) const {
        // One test for all four edges (a negative index wraps to a large one).
        const auto side = static_cast<unsigned>(grid_.per_side());
        if ((static_cast<unsigned>(column) >= side) | (static_cast<unsigned>(row) >= side)) return;
        members_.for_each_in(grid_.cell_at(column, row), visit);
    }

    // visit(j) for every particle, cell by cell: neighbours come close
    // together, so their data is still in the caches when it is read again.
    template <typename Visit>
    void for_each_by_cell(Visit&& visit) const {
        for (std::uint32_t cell = 0; cell < grid_.cell_count(); ++cell) members_.for_each_in(cell, visit);
    }

private:
    UniformGrid grid_;
    BucketLists members_;  // particles by cell
};

}  // namespace particlesim
