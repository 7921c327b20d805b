#pragma once
// A uniform grid whose cells hold a fixed number of boxes (slots), each cell
// one cache line of single-precision bounds. Testing a box against a cell is
// then a fixed, branch-free four-lane comparison, whatever the cell holds:
// the grid search uses it for fast, sparse scenes, where each particle is
// binned many times a step and short, unpredictable loops over cell lists
// cost more than the comparisons themselves.
//
// Bounds are rounded outwards to float, so a float overlap is implied by the
// double one (a few more pairs tested, never one fewer). A box that does not
// find a free slot is refused; the caller keeps it aside.

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace particlesim {

// Bounds of a box, rounded outwards to float.
struct FloatBox {
    float min_x, min_y, max_x, max_y;
};

// Cells [x_first, x_last] x [y_first, y_last] of a grid.
struct CellRegion {
    int x_first, y_first, x_last, y_last;
};

// Rounding to float moves a value by at most 2^-24 of itself (or 2^-149 near
// zero); stepping 2^-20 of it (plus 1e-37) away first keeps the result on
// the safe side. For values well inside float's range (|value| < 1e37).
inline float float_at_most(double value) {
    return static_cast<float>(value - (std::abs(value) * 0x1p-20 + 1e-37));
}

inline float float_at_least(double value) {
    return static_cast<float>(value + (std::abs(value) * 0x1p-20 + 1e-37));
}

class SlotGrid {
public:
    static constexpr int slots = 4;
    using Lanes = float __attribute__((vector_size(16)));
    using LaneMask = std::int32_t __attribute__((vector_size(16)));

    // Plain arrays, read as lanes: writing one lane of a vector type would
    // go through a store and reload of the whole vector.
    struct alignas(64) Cell {
        float min_x[slots], min_y[slots], max_x[slots], max_y[slots];
    };

    // A side x side grid with an empty border on the left, the right and the
    // top, so that the half stencil of a cell (east and the three above)
    // never needs a bounds check.
    void reset(int side) {
        width_ = side + 2;
        // Every cell is empty between slices, so a larger grid serves a
        // smaller side as it is; growing leaves room for the side to vary.
        const auto count = static_cast<std::size_t>(width_) * static_cast<std::size_t>(side + 1);
        if (cells_.size() < count) {
            const std::size_t room = count + count / 4;
            cells_.assign(room, empty_cell());
            fill_.assign(room, 0);
            ids_.assign(room * slots, 0);
            occupied_.reserve(room);
        }
    }

    // Stores `box` of particle `id` in cell (cx, cy); false when the cell is full.
    bool insert(int cx, int cy, const FloatBox& box, std::uint32_t id) {
        const std::size_t at = index(cx, cy);
        const std::uint8_t slot = fill_[at];
        if (slot == slots) return false;
        if (slot == 0) occupied_.push_back(static_cast<std::uint32_t>(at));
        Cell& cell = cells_[at];
        cell.min_x[slot] = box.min_x;
        cell.min_y[slot] = box.min_y;
        cell.max_x[slot] = box.max_x;
        cell.max_y[slot] = box.max_y;
        ids_[at * slots + slot] = id;
        fill_[at] = static_cast<std::uint8_t>(slot + 1);
        return true;
    }

    // Empties every cell that was filled since the last clear.
    void clear() {
        for (const std::uint32_t at : occupied_) {
            cells_[at] = empty_cell();
            fill_[at] = 0;
        }
        occupied_.clear();
    }

    // Calls pair(id_a, id_b) once for every two overlapping boxes held by
    // the grid: each slot against the later slots of its cell, the cell to
    // the east and the three cells above. Boxes must fit a cell, so that
    // overlapping ones are always in neighbouring cells.
    template <typename Pair>
    void for_each_overlap(Pair&& pair) const {
        const std::size_t width = static_cast<std::size_t>(width_);
        for (const std::uint32_t at : occupied_) {
            const int filled = fill_[at];
            for (int slot = 0; slot < filled; ++slot) {
                const FloatBox box = box_at(at, slot);
                const LaneMask own = hit_lanes(at, box) & later_slots(slot);
                const LaneMask east = hit_lanes(at + 1, box);
                const LaneMask above_west = hit_lanes(at + width - 1, box);
                const LaneMask above = hit_lanes(at + width, box);
                const LaneMask above_east = hit_lanes(at + width + 1, box);
                // Most boxes meet nothing: one test of all lanes skips the rest.
                if (!any(own | east | above_west | above | above_east)) continue;
                const std::uint32_t id = ids_[at * slots + slot];
                report(at, bits(own), id, pair);
                report(at + 1, bits(east), id, pair);
                report(at + width - 1, bits(above_west), id, pair);
                report(at + width, bits(above), id, pair);
                report(at + width + 1, bits(above_east), id, pair);
            }
        }
    }

    // Calls found(id) for every box held in `region` that overlaps `box`.
    template <typename Found>
    void for_each_in_region(const CellRegion& region, const FloatBox& box, Found&& found) const {
        for (int cy = region.y_first; cy <= region.y_last; ++cy) {
            for (int cx = region.x_first; cx <= region.x_last; ++cx) {
                const std::size_t at = index(cx, cy);
                for (unsigned hits = bits(hit_lanes(at, box)); hits != 0; hits &= hits - 1) {
                    found(ids_[at * slots + static_cast<unsigned>(std::countr_zero(hits))]);
                }
            }
        }
    }

private:
    [[nodiscard]] std::size_t index(int cx, int cy) const {
        return static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(cx) + 1;
    }

    // Lane k all ones: slot k of cell `at` holds a box that overlaps `box`.
    [[nodiscard]] LaneMask hit_lanes(std::size_t at, const FloatBox& box) const {
        const Cell& cell = cells_[at];
        return (lanes(cell.min_x) <= box.max_x) & (box.min_x <= lanes(cell.max_x)) & (lanes(cell.min_y) <= box.max_y) &
               (box.min_y <= lanes(cell.max_y));
    }

    // Bit k set: lane k is set.
    static unsigned bits(const LaneMask& hits) {
        const LaneMask weighted = hits & LaneMask{1, 2, 4, 8};
        return static_cast<unsigned>(weighted[0] | weighted[1] | weighted[2] | weighted[3]);
    }

    static bool any(const LaneMask& hits) {
        std::uint64_t halves[2];
        std::memcpy(halves, &hits, sizeof halves);
        return (halves[0] | halves[1]) != 0;
    }

    static LaneMask later_slots(int slot) {
        const LaneMask lane{0, 1, 2, 3};
        return lane > slot;
    }

    static Cell empty_cell() {
        // An empty slot spans nothing: min = +inf, max = -inf overlaps no box.
        constexpr float inf = std::numeric_limits<float>::infinity();
        return {{inf, inf, inf, inf}, {inf, inf, inf, inf}, {-inf, -inf, -inf, -inf}, {-inf, -inf, -inf, -inf}};
    }

    static Lanes lanes(const float (&values)[slots]) {
        Lanes result;
        std::memcpy(&result, values, sizeof result);
        return result;
    }

    [[nodiscard]] FloatBox box_at(std::size_t at, int slot) const {
        const Cell& cell = cells_[at];
        return {cell.min_x[slot], cell.min_y[slot], cell.max_x[slot], cell.max_y[slot]};
    }

    template <typename Pair>
    void report(std::size_t at, unsigned hits, std::uint32_t id, Pair& pair) const {
        for (; hits != 0; hits &= hits - 1) pair(id, ids_[at * slots + static_cast<unsigned>(std::countr_zero(hits))]);
    }

    int width_ = 2;
    std::vector<Cell> cells_;
    std::vector<std::uint8_t> fill_;
    std::vector<std::uint32_t> ids_;
    std::vector<std::uint32_t> occupied_;
};

}  // namespace particlesim
