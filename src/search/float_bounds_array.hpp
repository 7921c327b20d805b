#pragma once
// Swept boxes in single precision, 16 bytes each, stored one row per bound,
// so that the grid search tests a box against four stored boxes with four
// loads and one four-lane comparison. (Stored a box a row, the four boxes had
// to be turned into rows by six shuffles per group: 17 % more instructions
// on the default scene. Scattering a box into cell order is four stores
// instead of one; the dense gas did not notice, docs/benchmarks.md. Where
// lines are stored too, boxes are placed as records and turned into rows
// afterwards: box_records.hpp.)
// Most tested boxes miss, in no predictable pattern: branch-free lanes with
// one test per group of four cost far less than a compare-and-branch per box.
//
// Bounds are rounded outwards to float, so a float overlap is implied by the
// double one: a few more pairs get the exact pair test, never one fewer.
//
// Beside each box, its particle's line in float (line_test.hpp): where paths
// are long, most boxes that overlap belong to particles that pass far from
// each other, and a scan that also tests the lines, in the same lanes, hands
// on about one pair in forty of those (docs/benchmarks.md).

#include "search/line_test.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim {

// Bounds of a box, rounded outwards to float.
struct FloatBounds {
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

class FloatBoundsArray {
public:
    // Boxes tested by one comparison: four everywhere, eight where the
    // caller is compiled for eight-lane registers (AVX), sixteen (x86-64)
    // where the processor has AVX-512.
    static constexpr std::uint32_t lanes = 4;
    static constexpr std::uint32_t wide_lanes = 8;
    static constexpr std::uint32_t widest_lanes = 16;

    static constexpr std::uint32_t max_block_groups = 8;

    // Room for `count` boxes, plus padding that block scans may read (and
    // mask off) past the last box.
    void resize(std::size_t count) {
        for (std::vector<float>& row : bounds_) row.resize(count + max_block_groups * widest_lanes, 0.0f);
    }
    void reserve(std::size_t count) {
        for (std::vector<float>& row : bounds_) row.reserve(count + max_block_groups * widest_lanes);
    }
    // Room for the lines of as many boxes as resize() made room for: taken
    // only where scans may test lines (the dense gas's never do).
    void resize_lines() {
        for (std::vector<float>& row : lines_) {
            if (row.size() < bounds_[min_x].size()) row.resize(bounds_[min_x].size(), 0.0f);
        }
    }
    [[nodiscard]] bool holds_lines() const { return lines_[position_x].size() >= bounds_[min_x].size(); }

    void set(std::uint32_t at, const FloatBounds& box) {
        bounds_[min_x][at] = box.min_x;
        bounds_[min_y][at] = box.min_y;
        bounds_[max_x][at] = box.max_x;
        bounds_[max_y][at] = box.max_y;
    }

    [[nodiscard]] FloatBounds operator[](std::uint32_t at) const {
        return {bounds_[min_x][at], bounds_[min_y][at], bounds_[max_x][at], bounds_[max_y][at]};
    }

    // The line of the particle whose box is at `at`; read only by scans with lines.
    void set_line(std::uint32_t at, const FloatLine& line) {
        lines_[position_x][at] = line.x;
        lines_[position_y][at] = line.y;
        lines_[velocity_x][at] = line.vx;
        lines_[velocity_y][at] = line.vy;
    }
    [[nodiscard]] FloatLine line(std::uint32_t at) const {
        return {lines_[position_x][at], lines_[position_y][at], lines_[velocity_x][at], lines_[velocity_y][at]};
    }

    // Its rows: the four bounds, then the line's four components (BoxRecord's
    // order). The lines' are empty before resize_lines().
    [[nodiscard]] std::array<float*, 8> rows() {
        return {bounds_[min_x].data(),     bounds_[min_y].data(),     bounds_[max_x].data(),
                bounds_[max_y].data(),     lines_[position_x].data(), lines_[position_y].data(),
                lines_[velocity_x].data(), lines_[velocity_y].data()};
    }

    // Calls found(m) for every stored box m in [first, last) that overlaps
    // `box`. The range is tested in blocks of `block_groups` groups of
    // `group_lanes` boxes, the first one always: a range that fits one block
    // costs no branch on its length or on which of its groups hit, only one
    // on whether any did. Always inlined, so that a caller compiled for AVX
    // gets its eight lanes.
    template <std::uint32_t block_groups, std::uint32_t group_lanes = lanes, typename Found>
    [[gnu::always_inline]] void for_each_overlap(std::uint32_t first, std::uint32_t last, const FloatBounds& box,
                                                 Found&& found) const {
        for_each_close<block_groups, group_lanes, false>(first, last, box, FloatLine{}, LineTerms{}, found);
    }

    // The same, for the boxes that overlap `box` and whose lines also pass
    // the line test against `line` with `terms` (or every overlapping box
    // when `with_lines` is false). Sixteen lanes need a caller compiled for
    // AVX-512 on a processor that has it.
    template <std::uint32_t block_groups, std::uint32_t group_lanes, bool with_lines, typename Found>
    [[gnu::always_inline]] void for_each_close(std::uint32_t first, std::uint32_t last, const FloatBounds& box,
                                               const FloatLine& line, const LineTerms& terms, Found&& found) const {
        static_assert(block_groups >= 1 && block_groups <= max_block_groups);
        static_assert(group_lanes == lanes || group_lanes == wide_lanes || group_lanes == widest_lanes);
        static_assert(block_groups * group_lanes <= 64, "a block's hits fit one 64-bit word");
        constexpr std::uint32_t block = block_groups * group_lanes;
        std::uint32_t start = first;
        do {
            std::uint64_t hits = 0;
            for (std::uint32_t group = 0; group < block_groups; ++group) {
                hits |= std::uint64_t{hit_bits<group_lanes, with_lines>(start + group * group_lanes, box, line, terms)}
                        << (group * group_lanes);
            }
            const std::uint32_t inside = last > start ? std::min(last - start, block) : 0U;
            hits &= inside == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << inside) - 1U;
            for (; hits != 0; hits &= hits - 1) found(start + static_cast<std::uint32_t>(std::countr_zero(hits)));
            start += block;
        } while (start < last);
    }

private:
    enum Bound { min_x, min_y, max_x, max_y, bound_count };
    enum LineComponent { position_x, position_y, velocity_x, velocity_y, line_component_count };

#if defined(__x86_64__)
    // hit_bits() in sixteen lanes: the comparisons go into mask registers
    // (GCC compiles a sixteen-lane comparison of the vector extension lane by
    // lane). The same tests; a fused multiply-add only rounds less, and the
    // line test's margin holds either way. Not forced inline: it may only be
    // inlined into a caller compiled for AVX-512 (GridSearch's scan).
    template <bool with_lines>
    [[gnu::target("avx512f,fma")]] unsigned hit_bits_sixteen(std::uint32_t group, const FloatBounds& box,
                                                             const FloatLine& line, const LineTerms& terms) const {
        __mmask16 hits =
            _mm512_cmp_ps_mask(_mm512_loadu_ps(bounds_[min_x].data() + group), _mm512_set1_ps(box.max_x), _CMP_LE_OQ);
        hits = _mm512_mask_cmp_ps_mask(hits, _mm512_set1_ps(box.min_x), _mm512_loadu_ps(bounds_[max_x].data() + group),
                                       _CMP_LE_OQ);
        hits = _mm512_mask_cmp_ps_mask(hits, _mm512_loadu_ps(bounds_[min_y].data() + group), _mm512_set1_ps(box.max_y),
                                       _CMP_LE_OQ);
        hits = _mm512_mask_cmp_ps_mask(hits, _mm512_set1_ps(box.min_y), _mm512_loadu_ps(bounds_[max_y].data() + group),
                                       _CMP_LE_OQ);
        if constexpr (with_lines) {
            SixteenFloats cross_sq, bound;
            line_sides<SixteenFloats>(group, line, terms, cross_sq, bound);
            hits = _mm512_mask_cmp_ps_mask(hits, static_cast<__m512>(cross_sq), static_cast<__m512>(bound), _CMP_LE_OQ);
        }
        return hits;
    }
#endif

    // The line test's two sides (line_test.hpp) for the stored lines of group + 0 ... lanes - 1.
    template <typename Lanes>
    [[gnu::always_inline]] void line_sides(std::uint32_t group, const FloatLine& line, const LineTerms& terms,
                                           Lanes& cross_sq, Lanes& bound) const {
        Lanes x, y, vx, vy;
        std::memcpy(&x, &lines_[position_x][group], sizeof(Lanes));
        std::memcpy(&y, &lines_[position_y][group], sizeof(Lanes));
        std::memcpy(&vx, &lines_[velocity_x][group], sizeof(Lanes));
        std::memcpy(&vy, &lines_[velocity_y][group], sizeof(Lanes));
        line_test_sides(x, y, vx, vy, line, terms, cross_sq, bound);
    }

    // (A vector size that depends on a template parameter is ignored by GCC.)
    using FourFloats = float __attribute__((vector_size(16)));
    using FourInts = std::int32_t __attribute__((vector_size(16)));
    using EightFloats = float __attribute__((vector_size(32)));
    using SixteenFloats = float __attribute__((vector_size(64)));
    using EightInts = std::int32_t __attribute__((vector_size(32)));

    // Bit k set: box group + k overlaps `box`. No vector is passed or
    // returned by value: eight-lane ones would change the calling convention
    // of a build without AVX.
    template <std::uint32_t group_lanes, bool with_lines>
    [[gnu::always_inline]] unsigned hit_bits(std::uint32_t group, const FloatBounds& box, const FloatLine& line,
                                             const LineTerms& terms) const {
#if defined(__x86_64__)
        if constexpr (group_lanes == widest_lanes) return hit_bits_sixteen<with_lines>(group, box, line, terms);
#else
        static_assert(group_lanes != widest_lanes, "sixteen lanes are x86-64's");
#endif
        using Lanes = std::conditional_t<group_lanes == lanes, FourFloats, EightFloats>;
        using LaneMask = std::conditional_t<group_lanes == lanes, FourInts, EightInts>;
        Lanes low_x, low_y, high_x, high_y;
        std::memcpy(&low_x, &bounds_[min_x][group], sizeof(Lanes));
        std::memcpy(&low_y, &bounds_[min_y][group], sizeof(Lanes));
        std::memcpy(&high_x, &bounds_[max_x][group], sizeof(Lanes));
        std::memcpy(&high_y, &bounds_[max_y][group], sizeof(Lanes));
        LaneMask hits = (low_x <= box.max_x) & (box.min_x <= high_x) & (low_y <= box.max_y) & (box.min_y <= high_y);
        if constexpr (with_lines) {
            Lanes cross_sq, bound;
            line_sides<Lanes>(group, line, terms, cross_sq, bound);
            hits &= cross_sq <= bound;
        }
#if defined(__SSE__)
        // Every lane is all ones or all zeros: its sign bit is its hit bit,
        // taken four lanes at a time.
        unsigned bits = 0;
        for (std::uint32_t quarter = 0; quarter < group_lanes / 4; ++quarter) {
            FourFloats four;
            std::memcpy(&four, reinterpret_cast<const char*>(&hits) + quarter * sizeof four, sizeof four);
            bits |= static_cast<unsigned>(__builtin_ia32_movmskps(four)) << (4 * quarter);
        }
        return bits;
#else
        unsigned bits = 0;
        for (std::uint32_t lane = 0; lane < group_lanes; ++lane) bits |= hits[lane] != 0 ? 1U << lane : 0U;
        return bits;
#endif
    }

    std::vector<float> bounds_[bound_count];          // one row per bound
    std::vector<float> lines_[line_component_count];  // one row per component
};

}  // namespace particlesim
