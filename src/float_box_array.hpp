#pragma once
// Swept boxes in single precision, 16 bytes each, stored one row per bound,
// so that the grid search tests a box against four stored boxes with four
// loads and one four-lane comparison. (Stored a box a row, the four boxes had
// to be turned into rows by six shuffles per group: 17 % more instructions
// on the default scene. Scattering a box into cell order is four stores
// instead of one; the dense gas did not notice, docs/benchmarks.md.)
// Most tested boxes miss, in no predictable pattern: branch-free lanes with
// one test per group of four cost far less than a compare-and-branch per box.
//
// Bounds are rounded outwards to float, so a float overlap is implied by the
// double one: a few more pairs get the exact pair test, never one fewer.

#include <algorithm>
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

// Rounding to float moves a value by at most 2^-24 of itself (or 2^-149 near
// zero); stepping 2^-20 of it (plus 1e-37) away first keeps the result on the
// safe side. Beyond float's range a bound opens to infinity, or stays at the
// largest float on the safe side. Selects, not branches: this runs for every
// binned box.
inline float float_at_most(double value) {
    constexpr double largest = std::numeric_limits<float>::max();
    const double lowered = value - (std::abs(value) * 0x1p-20 + 1e-37);
    const auto converted = static_cast<float>(std::min(std::max(lowered, -largest), largest));
    return lowered < -largest ? -std::numeric_limits<float>::infinity() : converted;
}

inline float float_at_least(double value) {
    constexpr double largest = std::numeric_limits<float>::max();
    const double raised = value + (std::abs(value) * 0x1p-20 + 1e-37);
    const auto converted = static_cast<float>(std::min(std::max(raised, -largest), largest));
    return raised > largest ? std::numeric_limits<float>::infinity() : converted;
}

class FloatBoxArray {
public:
    static constexpr std::uint32_t lanes = 4;

    static constexpr std::uint32_t max_block_groups = 8;

    // Room for `count` boxes, plus padding that block scans may read (and
    // mask off) past the last box.
    void resize(std::size_t count) {
        for (std::vector<float>& bound : bounds_) bound.resize(count + max_block_groups * lanes, 0.0f);
    }

    void set(std::uint32_t at, const FloatBox& box) {
        bounds_[min_x][at] = box.min_x;
        bounds_[min_y][at] = box.min_y;
        bounds_[max_x][at] = box.max_x;
        bounds_[max_y][at] = box.max_y;
    }

    [[nodiscard]] FloatBox operator[](std::uint32_t at) const {
        return {bounds_[min_x][at], bounds_[min_y][at], bounds_[max_x][at], bounds_[max_y][at]};
    }

    // Calls found(m) for every stored box m in [first, last) that overlaps
    // `box`. The range is tested in blocks of `block_groups` groups, the
    // first one always: a range that fits one block costs no branch on its
    // length or on which of its groups hit, only one on whether any did.
    template <std::uint32_t block_groups, typename Found>
    void for_each_overlap(std::uint32_t first, std::uint32_t last, const FloatBox& box, Found&& found) const {
        static_assert(block_groups >= 1 && block_groups <= max_block_groups);
        constexpr std::uint32_t block = block_groups * lanes;
        std::uint32_t start = first;
        do {
            std::uint64_t hits = 0;
            for (std::uint32_t group = 0; group < block_groups; ++group) {
                hits |= std::uint64_t{hit_bits(start + group * lanes, box)} << (group * lanes);
            }
            const std::uint32_t inside = last > start ? std::min(last - start, block) : 0U;
            hits &= (std::uint64_t{1} << inside) - 1U;
            for (; hits != 0; hits &= hits - 1) found(start + static_cast<std::uint32_t>(std::countr_zero(hits)));
            start += block;
        } while (start < last);
    }

private:
    enum Bound { min_x, min_y, max_x, max_y, bound_count };

    using Lanes = float __attribute__((vector_size(16)));
    using LaneMask = std::int32_t __attribute__((vector_size(16)));

    [[nodiscard]] Lanes load(Bound bound, std::uint32_t at) const {
        Lanes result;
        std::memcpy(&result, &bounds_[bound][at], sizeof result);
        return result;
    }

    // Bit k set: box group + k overlaps `box`.
    [[nodiscard]] unsigned hit_bits(std::uint32_t group, const FloatBox& box) const {
        const LaneMask hits = (load(min_x, group) <= box.max_x) & (box.min_x <= load(max_x, group)) &
                              (load(min_y, group) <= box.max_y) & (box.min_y <= load(max_y, group));
#if defined(__SSE__)
        // Every lane is all ones or all zeros: its sign bit is its hit bit.
        return static_cast<unsigned>(__builtin_ia32_movmskps(reinterpret_cast<Lanes>(hits)));
#else
        const LaneMask weighted = hits & LaneMask{1, 2, 4, 8};
        return static_cast<unsigned>(weighted[0] | weighted[1] | weighted[2] | weighted[3]);
#endif
    }

    std::vector<float> bounds_[bound_count];  // one row per bound
};

}  // namespace particlesim
