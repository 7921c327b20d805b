#pragma once
// The one uniform grid every cell structure of the library is built on (the
// pair search, the exact engine's neighbour cells, the storage order, random
// placement, the overlap count): how many cells a side, and which cell a point
// falls in. Each user decides how fine it wants the grid; this decides the
// rest the same way for all of them.

#include "particlesim/particle.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace particlesim {

// A periodic box's neighbour cells (the exact engine's, the compression's) need
// five a side or more: the 3 x 3 cells around a disk are then nine different
// cells, and two disks in neighbouring cells are less than half the box apart,
// so the nearest image is the one that meets.
inline constexpr int periodic_cells_at_least = 5;

class UniformGrid {
public:
    // The most cells a side no narrower than `min_cell_size` (with a margin,
    // so that rounding cannot make one narrower), at most `max_per_side`, at
    // least 1. A `min_cell_size` of 0 leaves only the maximum.
    static int cells_per_side(double extent, double min_cell_size, double max_per_side) {
        constexpr double rounding_margin = 1.0 + 1e-6;
        constexpr double largest_side = 65536.0;  // cell counts stay within 32-bit indices
        const double by_size =
            min_cell_size > 0.0 ? std::floor(extent / (min_cell_size * rounding_margin)) : largest_side;
        return static_cast<int>(std::clamp(std::min(by_size, std::floor(max_per_side)), 1.0, largest_side));
    }

    UniformGrid() = default;
    // `per_side` x `per_side` cells over [0, extent]^2.
    UniformGrid(double extent, int per_side)
        : per_side_(per_side), cell_size_(extent / per_side), inverse_cell_size_(1.0 / cell_size_) {}

    [[nodiscard]] int per_side() const { return per_side_; }
    [[nodiscard]] double cell_size() const { return cell_size_; }
    [[nodiscard]] std::size_t cell_count() const {
        return static_cast<std::size_t>(per_side_) * static_cast<std::size_t>(per_side_);
    }

    // The column (or row) a coordinate falls in, clamped to the grid:
    // coordinates below it (and NaN) map to 0, above it to the last.
    [[nodiscard]] int column_of(double coordinate) const {
        const double scaled = coordinate * inverse_cell_size_;
        if (!(scaled > 0.0)) return 0;
        if (scaled >= per_side_) return per_side_ - 1;
        return static_cast<int>(scaled);
    }
    // Cells are numbered row by row.
    [[nodiscard]] std::uint32_t cell_at(int column, int row) const {
        return static_cast<std::uint32_t>(row) * static_cast<std::uint32_t>(per_side_) +
               static_cast<std::uint32_t>(column);
    }
    [[nodiscard]] std::uint32_t cell_of(double x, double y) const { return cell_at(column_of(x), column_of(y)); }
    [[nodiscard]] std::uint32_t cell_of(const Vec2& point) const { return cell_of(point.x(), point.y()); }
    [[nodiscard]] int column(std::uint32_t cell) const {
        return static_cast<int>(cell % static_cast<std::uint32_t>(per_side_));
    }
    [[nodiscard]] int row(std::uint32_t cell) const {
        return static_cast<int>(cell / static_cast<std::uint32_t>(per_side_));
    }

private:
    int per_side_ = 1;
    double cell_size_ = 1.0;
    double inverse_cell_size_ = 1.0;
};

}  // namespace particlesim
