// The exact engine's two ways of keeping the particles by cell (linked lists
// through the particles, and records holding each cell's first members with
// the rest listed), under random inserts and moves against a plain set per
// cell: few cells and many particles, so that most cells overflow their
// records and members are promoted from the lists into freed slots; many
// cells and few particles, so that most stay empty. Every cell is compared
// after every move, both ways, and each particle's cell.

#include "check.hpp"

#include "core/random.hpp"
#include "core/uniform_grid.hpp"
#include "exact/cell_list.hpp"

#include <algorithm>
#include <vector>

namespace {

// A broken list may loop: the visit stops (by throwing) past every particle.
struct EndlessCell {};

std::vector<std::uint32_t> members_of(const particlesim::CellList& cells, std::uint32_t cell, std::uint32_t particles) {
    std::vector<std::uint32_t> members;
    const int side = cells.grid().per_side();
    try {
        cells.for_each_in(static_cast<int>(cell) % side, static_cast<int>(cell) / side, [&](std::uint32_t j) {
            if (members.size() > particles) throw EndlessCell{};
            members.push_back(j);
        });
    } catch (const EndlessCell&) {
        return {particles};  // no particle has this index
    }
    std::sort(members.begin(), members.end());
    return members;
}

void matches_reference(int side, std::uint32_t particles, bool in_records, std::uint64_t seed) {
    const particlesim::UniformGrid grid(1.0, side);
    const auto cell_count = static_cast<std::uint32_t>(grid.cell_count());
    particlesim::CellList cells(grid, particles, in_records);
    CHECK(cells.in_records() == in_records);
    particlesim::SplitMix64 rng(seed);
    std::vector<std::vector<std::uint32_t>> reference(cell_count);
    std::vector<std::uint32_t> cell_of(particles);
    for (std::uint32_t i = 0; i < particles; ++i) {
        cell_of[i] = static_cast<std::uint32_t>(rng.next() % cell_count);
        cells.insert(i, cell_of[i]);
        reference[cell_of[i]].push_back(i);
    }
    int wrong_cells = 0;
    int wrong_places = 0;
    const auto compare_all = [&] {
        for (std::uint32_t cell = 0; cell < cell_count; ++cell) {
            std::vector<std::uint32_t> expected = reference[cell];
            std::sort(expected.begin(), expected.end());
            wrong_cells += members_of(cells, cell, particles) == expected ? 0 : 1;
        }
        for (std::uint32_t i = 0; i < particles; ++i) wrong_places += cells.cell_of_particle(i) == cell_of[i] ? 0 : 1;
    };
    compare_all();
    for (int move = 0; move < 2000; ++move) {
        const auto i = static_cast<std::uint32_t>(rng.next() % particles);
        // Often into the cell it is in, or a neighbour's: the engine's moves.
        const auto to = static_cast<std::uint32_t>(rng.next() % 4 == 0 ? cell_of[i] : rng.next() % cell_count);
        std::vector<std::uint32_t>& from = reference[cell_of[i]];
        from.erase(std::find(from.begin(), from.end(), i));
        reference[to].push_back(i);
        cell_of[i] = to;
        if (in_records) {
            cells.move<particlesim::CellRecords>(i, to);
        } else {
            cells.move<particlesim::BucketLists>(i, to);
        }
        if (move % 50 == 0) compare_all();
    }
    compare_all();
    CHECK_EQ(wrong_cells, 0);
    CHECK_EQ(wrong_places, 0);
    // The visits saw every particle once.
    std::size_t visited = 0;
    if (wrong_cells == 0) cells.for_each_by_cell([&](std::uint32_t) { ++visited; });
    if (wrong_cells == 0) CHECK_EQ(visited, std::size_t{particles});
}

void both_ways(bool in_records) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        matches_reference(2, 40, in_records, seed);     // ten a cell: long overflow lists
        matches_reference(4, 40, in_records, seed);     // 2.5 a cell: slots and lists both
        matches_reference(16, 30, in_records, seed);    // mostly empty cells
        matches_reference(64, 5000, in_records, seed);  // about one a cell
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_cell_members",
                      {{"linked lists against a set per cell", [] { both_ways(false); }},
                       {"records against a set per cell", [] { both_ways(true); }}});
}
