#pragma once
// Swept boxes in single precision, 16 bytes each, so that the grid search
// tests a box against four stored boxes with one four-lane comparison (after
// turning the four boxes into one row per bound). One box is one store when
// the grid scatters boxes into cell order, which matters for dense scenes.
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

class FloatBoxArray {
public:
    static constexpr std::uint32_t lanes = 4;

    // Room for `count` boxes, plus a padding group that range scans may read
    // (and mask off) past the last box.
    void resize(std::size_t count) { boxes_.resize(count + lanes, FloatBox{0.0f, 0.0f, 0.0f, 0.0f}); }

    void set(std::uint32_t at, const FloatBox& box) { boxes_[at] = box; }

    [[nodiscard]] FloatBox operator[](std::uint32_t at) const { return boxes_[at]; }

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

    [[nodiscard]] Lanes load(std::uint32_t at) const {
        Lanes result;
        std::memcpy(&result, &boxes_[at], sizeof result);
        return result;
    }

    // Bit k set: box group + k overlaps `box`.
    [[nodiscard]] unsigned hit_bits(std::uint32_t group, const FloatBox& box) const {
        // Four boxes, one a row, turned into one row per bound.
        const Lanes a = load(group), b = load(group + 1), c = load(group + 2), d = load(group + 3);
        const Lanes ab_low = __builtin_shufflevector(a, b, 0, 4, 1, 5),
                    cd_low = __builtin_shufflevector(c, d, 0, 4, 1, 5);
        const Lanes ab_high = __builtin_shufflevector(a, b, 2, 6, 3, 7),
                    cd_high = __builtin_shufflevector(c, d, 2, 6, 3, 7);
        const Lanes min_x = __builtin_shufflevector(ab_low, cd_low, 0, 1, 4, 5);
        const Lanes min_y = __builtin_shufflevector(ab_low, cd_low, 2, 3, 6, 7);
        const Lanes max_x = __builtin_shufflevector(ab_high, cd_high, 0, 1, 4, 5);
        const Lanes max_y = __builtin_shufflevector(ab_high, cd_high, 2, 3, 6, 7);
        const LaneMask hits = (min_x <= box.max_x) & (box.min_x <= max_x) & (min_y <= box.max_y) & (box.min_y <= max_y);
        std::uint64_t halves[2];
        std::memcpy(halves, &hits, sizeof halves);
        if ((halves[0] | halves[1]) == 0) return 0;
        const LaneMask weighted = hits & LaneMask{1, 2, 4, 8};
        return static_cast<unsigned>(weighted[0] | weighted[1] | weighted[2] | weighted[3]);
    }

    std::vector<FloatBox> boxes_;
};

}  // namespace particlesim
