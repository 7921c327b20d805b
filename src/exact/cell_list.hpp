#pragma once
// A uniform grid of cells and the particles in each, so that a particle
// moves between cells in O(1). Cells are at least a diameter wide: two disks
// in contact are in the same or adjacent cells. The members are kept one of
// two ways, chosen once: each cell a linked list through the particles
// (bucket_lists.hpp), or each cell's first members in a record of its own
// (cell_records.hpp), for states far larger than the caches.

#include "core/uniform_grid.hpp"
#include "exact/bucket_lists.hpp"
#include "exact/cell_records.hpp"

#include <algorithm>
#include <cstdint>
#include <type_traits>

namespace particlesim {

class CellList {
public:
    // The way not chosen stays empty.
    CellList(const UniformGrid& grid, std::size_t particle_count, bool in_records)
        : grid_(grid),
          in_records_(in_records),
          lists_(in_records ? 0 : grid.cell_count(), in_records ? 0 : particle_count),
          records_(in_records ? grid.cell_count() : 0, in_records ? particle_count : 0) {}

    [[nodiscard]] const UniformGrid& grid() const { return grid_; }
    [[nodiscard]] bool in_records() const { return in_records_; }
    [[nodiscard]] std::uint32_t cell_of_particle(std::uint32_t particle) const {
        return in_records_ ? records_.bucket_of(particle) : lists_.bucket_of(particle);
    }

    // For prefetching, the 3 x 3 cells around `cell`, as three runs of
    // three cell indices, without divisions: at the grid's edges a run may
    // end in the next row or start in the last (a wasted prefetch), but
    // never leaves the grid. Needs 2 x 2 cells or more.
    template <typename Members>
    void prefetch_cells_around(const Members& members, std::uint32_t cell) const {
        for_each_run_around(cell, [&](std::uint32_t start) {
            prefetch_cell(members, start);
            prefetch_cell(members, start + 2);
        });
    }
    // visit(member) for the members those cells name without a further read
    // (their lists' first members, or the members in their records; `none`
    // where there is none); a list's next link is fetched too.
    template <typename Members, typename Visit>
    void for_each_named_member_around(const Members& members, std::uint32_t cell, Visit&& visit) const {
        for_each_run_around(cell, [&](std::uint32_t start) {
            for (std::uint32_t c = start; c < start + 3; ++c) visit_named_members(members, c, visit);
        });
    }
    // Where the particle's membership is kept.
    static void prefetch_place(const BucketLists& lists, std::uint32_t particle) { lists.prefetch_links(particle); }
    static void prefetch_place(const CellRecords& records, std::uint32_t particle) { records.prefetch_place(particle); }

    void insert(std::uint32_t particle, std::uint32_t cell) {
        if (in_records_) {
            records_.insert(particle, cell);
        } else {
            lists_.insert(particle, cell);
        }
    }

    // The members' storage, BucketLists or CellRecords (the one chosen:
    // in_records()), for code compiled for each.
    template <typename Members>
    [[nodiscard]] const Members& storage() const {
        if constexpr (std::is_same_v<Members, CellRecords>) {
            return records_;
        } else {
            return lists_;
        }
    }
    template <typename Members>
    void move(std::uint32_t particle, std::uint32_t cell) {
        if constexpr (std::is_same_v<Members, CellRecords>) {
            records_.move(particle, cell);
        } else {
            lists_.move(particle, cell);
        }
    }

    // body(members) with the members' storage (BucketLists or CellRecords,
    // both with for_each_in(cell, visit)), for code outside the event loop:
    // a search of several cells chooses once, not at every cell.
    template <typename Body>
    void with_members(Body&& body) const {
        if (in_records_) {
            body(records_);
        } else {
            body(lists_);
        }
    }
    // visit(j) for every particle in the cell at (column, row) of `members`
    // (this grid's storage, as with_members() gives it), if the cell exists.
    template <typename Members, typename Visit>
    void for_each_in(const Members& members, int column, int row, Visit&& visit) const {
        // One test for all four edges (a negative index wraps to a large one).
        const auto side = static_cast<unsigned>(grid_.per_side());
        if ((static_cast<unsigned>(column) >= side) | (static_cast<unsigned>(row) >= side)) return;
        members.for_each_in(grid_.cell_at(column, row), visit);
    }
    // The same in a periodic grid: indices one beyond an edge wrap around.
    template <typename Members, typename Visit>
    void for_each_in_wrapped(const Members& members, int column, int row, Visit&& visit) const {
        const int side = grid_.per_side();
        column += column < 0 ? side : column >= side ? -side : 0;
        row += row < 0 ? side : row >= side ? -side : 0;
        members.for_each_in(grid_.cell_at(column, row), visit);
    }

    // visit(j) for every particle in the cell at (column, row), if it exists.
    template <typename Visit>
    void for_each_in(int column, int row, Visit&& visit) const {
        with_members([&](const auto& members) { for_each_in(members, column, row, visit); });
    }

    // visit(j) for every particle, cell by cell: neighbours come close
    // together, so their data is still in the caches when it is read again.
    template <typename Visit>
    void for_each_by_cell(Visit&& visit) const {
        for (std::uint32_t cell = 0; cell < grid_.cell_count(); ++cell) for_each_in(cell, visit);
    }

    // visit(j) for every particle in `cell`.
    template <typename Visit>
    void for_each_in(std::uint32_t cell, Visit&& visit) const {
        if (in_records_) {
            records_.for_each_in(cell, visit);
        } else {
            lists_.for_each_in(cell, visit);
        }
    }

private:
    static void prefetch_cell(const BucketLists& lists, std::uint32_t cell) { lists.prefetch_head(cell); }
    static void prefetch_cell(const CellRecords& records, std::uint32_t cell) { records.prefetch_record(cell); }
    template <typename Visit>
    static void visit_named_members(const BucketLists& lists, std::uint32_t cell, Visit&& visit) {
        const std::uint32_t first = lists.first(cell);
        visit(first);
        lists.prefetch_links(first);
    }
    template <typename Visit>
    static void visit_named_members(const CellRecords& records, std::uint32_t cell, Visit&& visit) {
        records.for_each_slot(cell, visit);
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
    bool in_records_;
    BucketLists lists_;    // particles by cell, as lists
    CellRecords records_;  // or in records
};

}  // namespace particlesim
