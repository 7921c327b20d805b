#pragma once
// Swept boxes in single precision, one column per bound, so that the grid
// search tests a box against four stored boxes with one four-lane comparison.
// Most tested boxes miss, in no predictable pattern: branch-free lanes with
// one test per group of four cost far less than a compare-and-branch per box.
//
// Bounds are rounded outwards to float, so a float overlap is implied by the
// double one: a few more pairs get the exact pair test, never one fewer.

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

class BoxColumns {
public:
    static constexpr std::uint32_t lanes = 4;

    // Room for `count` boxes, plus a padding group that range scans may read
    // (and mask off) past the last box.
    void resize(std::size_t count) {
        for (std::vector<float>* column : {&min_x_, &min_y_, &max_x_, &max_y_}) column->resize(count + lanes, 0.0f);
    }

    void set(std::uint32_t at, const FloatBox& box) {
        min_x_[at] = box.min_x;
        min_y_[at] = box.min_y;
        max_x_[at] = box.max_x;
        max_y_[at] = box.max_y;
    }

    [[nodiscard]] FloatBox operator[](std::uint32_t at) const { return {min_x_[at], min_y_[at], max_x_[at], max_y_[at]}; }

    // Calls found(m) for every stored box m in [first, last) that overlaps `box`.
    template <typename Found>
    void for_each_overlap(std::uint32_t first, std::uint32_t last, const FloatBox& box, Found&& found) const {
        for (std::uint32_t group = first; group < last; group += lanes) {
            unsigned hits = hit_bits(group, box);
            if (hits == 0) continue;
            if (last - group < lanes) hits &= (1U << (last - group)) - 1U;
            for (; hits != 0; hits &= hits - 1) found(group + static_cast<std::uint32_t>(std::countr_zero(hits)));
        }
    }

private:
    using Lanes = float __attribute__((vector_size(16)));
    using LaneMask = std::int32_t __attribute__((vector_size(16)));

    static Lanes load(const std::vector<float>& column, std::uint32_t at) {
        Lanes result;
        std::memcpy(&result, column.data() + at, sizeof result);
        return result;
    }

    // Bit k set: box group + k overlaps `box`.
    [[nodiscard]] unsigned hit_bits(std::uint32_t group, const FloatBox& box) const {
        const LaneMask hits = (load(min_x_, group) <= box.max_x) & (box.min_x <= load(max_x_, group)) &
                              (load(min_y_, group) <= box.max_y) & (box.min_y <= load(max_y_, group));
        std::uint64_t halves[2];
        std::memcpy(halves, &hits, sizeof halves);
        if ((halves[0] | halves[1]) == 0) return 0;
        const LaneMask weighted = hits & LaneMask{1, 2, 4, 8};
        return static_cast<unsigned>(weighted[0] | weighted[1] | weighted[2] | weighted[3]);
    }

    std::vector<float> min_x_, min_y_, max_x_, max_y_;
};

}  // namespace particlesim
