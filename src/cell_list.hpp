#pragma once
// A uniform grid of cells, each a doubly linked list of the particles in it,
// so that a particle moves between cells in O(1). Cells are at least a
// diameter wide: two disks in contact are in the same or adjacent cells.

#include <algorithm>
#include <cstdint>
#include <vector>

namespace particlesim {

class CellList {
public:
    static constexpr std::uint32_t none = 0xffffffffU;  // below any particle count the engines accept

    CellList(int cells_per_side, double box_size, std::size_t particle_count)
        : side_(cells_per_side), cell_size_(box_size / cells_per_side),
          head_(static_cast<std::size_t>(cells_per_side) * static_cast<std::size_t>(cells_per_side), none),
          next_(particle_count, none), previous_(particle_count, none), cell_(particle_count, 0) {}

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
    [[nodiscard]] std::uint32_t cell_of_particle(std::uint32_t particle) const { return cell_[particle]; }

    void insert(std::uint32_t particle, std::uint32_t cell) {
        cell_[particle] = cell;
        previous_[particle] = none;
        next_[particle] = head_[cell];
        if (head_[cell] != none) previous_[head_[cell]] = particle;
        head_[cell] = particle;
    }
    void remove(std::uint32_t particle) {
        const std::uint32_t before = previous_[particle];
        const std::uint32_t after = next_[particle];
        if (before != none) {
            next_[before] = after;
        } else {
            head_[cell_[particle]] = after;
        }
        if (after != none) previous_[after] = before;
    }
    void move(std::uint32_t particle, std::uint32_t cell) {
        remove(particle);
        insert(particle, cell);
    }

    // visit(j) for every particle in the cell at (column, row), if it exists.
    template <typename Visit>
    void for_each_in(int column, int row, Visit&& visit) const {
        if (column < 0 || row < 0 || column >= side_ || row >= side_) return;
        for (std::uint32_t j = head_[cell_at(column, row)]; j != none; j = next_[j]) visit(j);
    }

private:
    int side_;
    double cell_size_;
    std::vector<std::uint32_t> head_;
    std::vector<std::uint32_t> next_;
    std::vector<std::uint32_t> previous_;
    std::vector<std::uint32_t> cell_;
};

}  // namespace particlesim
