#pragma once
// A uniform grid of cells, each a linked list of the particles in it (see
// bucket_lists.hpp), so that a particle moves between cells in O(1). Cells are at least a
// diameter wide: two disks in contact are in the same or adjacent cells.

#include "bucket_lists.hpp"

#include <algorithm>
#include <cstdint>

namespace particlesim {

class CellList {
public:
    CellList(int cells_per_side, double box_size, std::size_t particle_count)
        : side_(cells_per_side), cell_size_(box_size / cells_per_side),
          members_(static_cast<std::size_t>(cells_per_side) * static_cast<std::size_t>(cells_per_side), particle_count) {}

    [[nodiscard]] int side() const { return side_; }
    [[nodiscard]] double cell_size() const { return cell_size_; }
    [[nodiscard]] int column_of(double coordinate) const {
        return std::clamp(static_cast<int>(coordinate / cell_size_), 0, side_ - 1);
    }
    [[nodiscard]] std::uint32_t cell_at(int column, int row) const {
        return static_cast<std::uint32_t>(row) * static_cast<std::uint32_t>(side_) + static_cast<std::uint32_t>(column);
    }
    [[nodiscard]] int column(std::uint32_t cell) const { return static_cast<int>(cell % static_cast<std::uint32_t>(side_)); }
    [[nodiscard]] int row(std::uint32_t cell) const { return static_cast<int>(cell / static_cast<std::uint32_t>(side_)); }
    [[nodiscard]] std::uint32_t cell_of_particle(std::uint32_t particle) const { return members_.bucket_of(particle); }

    void insert(std::uint32_t particle, std::uint32_t cell) { members_.insert(particle, cell); }
    void move(std::uint32_t particle, std::uint32_t cell) { members_.move(particle, cell); }

    // visit(j) for every particle in the cell at (column, row), if it exists.
    template <typename Visit>
    void for_each_in(int column, int row, Visit&& visit) const {
        if (column < 0 || row < 0 || column >= side_ || row >= side_) return;
        members_.for_each_in(cell_at(column, row), visit);
    }

private:
    int side_;
    double cell_size_;
    BucketLists members_;  // particles by cell
};

}  // namespace particlesim
