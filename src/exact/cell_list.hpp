#pragma once
// A uniform grid of cells, each a linked list of the particles in it (see
// bucket_lists.hpp), so that a particle moves between cells in O(1). Cells are at least a
// diameter wide: two disks in contact are in the same or adjacent cells. Each
// particle's record may hold more than its links (the exact engine's
// particle state; see BucketListsOf).

#include "core/uniform_grid.hpp"
#include "exact/bucket_lists.hpp"

#include <algorithm>
#include <cstdint>

namespace particlesim {

template <typename Record>
class CellListOf {
public:
    CellListOf(const UniformGrid& grid, std::size_t particle_count)
        : grid_(grid), members_(grid.cell_count(), particle_count) {}

    [[nodiscard]] Record& record(std::uint32_t particle) { return members_.record(particle); }
    [[nodiscard]] const Record& record(std::uint32_t particle) const { return members_.record(particle); }

    [[nodiscard]] const UniformGrid& grid() const { return grid_; }
    [[nodiscard]] std::uint32_t cell_of_particle(std::uint32_t particle) const { return members_.bucket_of(particle); }

    // For prefetching, the 3 x 3 cells around `cell`, as three runs of
    // three cell indices, without divisions: at the grid's edges a run may
    // end in the next row or start in the last (a wasted prefetch), but
    // never leaves the grid. Needs 2 x 2 cells or more.
    void prefetch_heads_around(std::uint32_t cell) const {
        for_each_run_around(cell, [&](std::uint32_t start) {
            members_.prefetch_head(start);
            members_.prefetch_head(start + 2);
        });
    }
    // visit(first) for the first member of each of those cells (none if empty).
    template <typename Visit>
    void for_each_first_member_around(std::uint32_t cell, Visit&& visit) const {
        for_each_run_around(cell, [&](std::uint32_t start) {
            for (std::uint32_t c = start; c < start + 3; ++c) visit(members_.first(c));
        });
    }
    // The same for three cells in a line, `middle` and its neighbours
    // `stride` away (1 along a row, the side along a column), clamped into
    // the grid: the cells a crossing searches.
    void prefetch_heads_of_three(std::int64_t middle, std::int64_t stride) const {
        for_each_of_three(middle, stride, [&](std::uint32_t cell) { members_.prefetch_head(cell); });
    }
    template <typename Visit>
    void for_each_first_member_of_three(std::int64_t middle, std::int64_t stride, Visit&& visit) const {
        for_each_of_three(middle, stride, [&](std::uint32_t cell) { visit(members_.first(cell)); });
    }
    void prefetch_head(std::uint32_t cell) const { members_.prefetch_head(cell); }
    [[nodiscard]] std::uint32_t first_member(std::uint32_t cell) const { return members_.first(cell); }
    void prefetch_links(std::uint32_t particle) const { members_.prefetch_links(particle); }
    // The links of the particles before and after it in its cell's list,
    // which moving it rewrites (its own links fetched already).
    void prefetch_list_neighbours(std::uint32_t particle) const {
        members_.prefetch_links(members_.next(particle));
        members_.prefetch_links(members_.previous(particle));
    }

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

    // BucketLists::gather() for the cell at (column, row), if it exists.
    std::size_t gather_in(int column, int row, std::uint32_t skipped, std::uint32_t* out, std::size_t k) const {
        const auto side = static_cast<unsigned>(grid_.per_side());
        if ((static_cast<unsigned>(column) >= side) | (static_cast<unsigned>(row) >= side)) return k;
        return members_.gather(grid_.cell_at(column, row), skipped, out, k);
    }
    // The same in a periodic grid: indices one beyond an edge wrap around.
    std::size_t gather_in_wrapped(int column, int row, std::uint32_t skipped, std::uint32_t* out, std::size_t k) const {
        return members_.gather(wrapped_cell(column, row), skipped, out, k);
    }

    // The same in a periodic grid: indices one beyond an edge wrap around.
    template <typename Visit>
    void for_each_in_wrapped(int column, int row, Visit&& visit) const {
        members_.for_each_in(wrapped_cell(column, row), visit);
    }

    // visit(j) for every particle, cell by cell: neighbours come close
    // together, so their data is still in the caches when it is read again.
    template <typename Visit>
    void for_each_by_cell(Visit&& visit) const {
        for (std::uint32_t cell = 0; cell < grid_.cell_count(); ++cell) members_.for_each_in(cell, visit);
    }

private:
    // The cell at (column, row) of a periodic grid, each index at most one
    // beyond an edge.
    [[nodiscard]] std::uint32_t wrapped_cell(int column, int row) const {
        const int side = grid_.per_side();
        column += column < 0 ? side : column >= side ? -side : 0;
        row += row < 0 ? side : row >= side ? -side : 0;
        return grid_.cell_at(column, row);
    }

    template <typename Visit>
    void for_each_of_three(std::int64_t middle, std::int64_t stride, Visit&& visit) const {
        const auto last = static_cast<std::int64_t>(grid_.cell_count()) - 1;
        for (std::int64_t k = -1; k <= 1; ++k) {
            visit(static_cast<std::uint32_t>(std::clamp(middle + k * stride, std::int64_t{0}, last)));
        }
    }

    template <typename Visit>
    void for_each_run_around(std::uint32_t cell, Visit&& visit) const {
        const auto side = static_cast<std::int64_t>(grid_.per_side());
        const auto last_start = static_cast<std::int64_t>(grid_.cell_count()) - 3;
        for (std::int64_t row = -1; row <= 1; ++row) {
            visit(static_cast<std::uint32_t>(std::clamp(cell + row * side - 1, std::int64_t{0}, last_start)));
        }
    }

    UniformGrid grid_;
    BucketListsOf<Record> members_;  // particles by cell
};

using CellList = CellListOf<BucketLinks>;

}  // namespace particlesim
