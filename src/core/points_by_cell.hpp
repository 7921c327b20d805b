#pragma once
// Points sorted by the cell of a uniform grid they fall in (a counting
// sort): the neighbour searches that look at the cells around a point.

#include "core/uniform_grid.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace particlesim {

class PointsByCell {
public:
    // point_of(k) for k in [0, count): where point k is.
    template <typename PointOf>
    PointsByCell(const UniformGrid& grid, std::uint32_t count, PointOf&& point_of)
        : grid_(grid), starts_(grid.cell_count() + 1, 0), members_(count) {
        for (std::uint32_t k = 0; k < count; ++k) ++starts_[grid_.cell_of(point_of(k)) + 1];
        for (std::size_t c = 0; c < grid_.cell_count(); ++c) starts_[c + 1] += starts_[c];
        std::vector<std::uint32_t> fill(starts_.begin(), starts_.end() - 1);
        for (std::uint32_t k = 0; k < count; ++k) members_[fill[grid_.cell_of(point_of(k))]++] = k;
    }

    [[nodiscard]] const UniformGrid& grid() const { return grid_; }

    // The points of the cell at (column, row), which must be in the grid, in
    // ascending order.
    [[nodiscard]] std::span<const std::uint32_t> in_cell(int column, int row) const {
        const std::uint32_t cell = grid_.cell_at(column, row);
        return std::span(members_).subspan(starts_[cell], starts_[cell + 1] - starts_[cell]);
    }

    // visit(k) for every point in the cell at (column, row), which must be in the grid.
    template <typename Visit>
    void for_each_in(int column, int row, Visit&& visit) const {
        const std::uint32_t cell = grid_.cell_at(column, row);
        for (std::uint32_t k = starts_[cell]; k < starts_[cell + 1]; ++k) visit(members_[k]);
    }

private:
    UniformGrid grid_;
    std::vector<std::uint32_t> starts_;  // by cell, where its members begin; one more at the end
    std::vector<std::uint32_t> members_;
};

}  // namespace particlesim
