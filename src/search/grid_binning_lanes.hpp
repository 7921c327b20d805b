#pragma once
// The grid search's binning of a slice, several paths at a time in vector
// lanes: the count (which cell each path's box falls in) and the placement
// (each box, in float, and its line, stored at its place in cell order), in
// eight lanes of AVX-512 or four of AVX2. Every lane carries out the scalar
// code's operations on the same doubles (selects where it takes std::min and
// std::max, the same clamps as UniformGrid::column_of()), so the placement
// finds each box in the cell the count put it in, and the searches' results
// do not depend on the lanes. Included by grid_search.cpp alone.

#include "core/uniform_grid.hpp"
#include "particlesim/particle.hpp"
#include "search/box_records.hpp"
#include "search/float_bounds_array.hpp"
#include "search/float_transpose.hpp"
#include "search/pair_search.hpp"
#include "stepped/stepped_tuning.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace particlesim::grid_binning {

// Marks in cell_of, above every cell index: not moving in the slice, large,
// and cut into k pieces (large_marker - k).
constexpr std::uint32_t absent_marker = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t large_marker = absent_marker - 1;
constexpr std::uint32_t first_piece_marker = large_marker - stepped_tuning::max_pieces;

// What the count reads of a slice.
struct CountInput {
    const Particle* particles;
    const double* wall_time;
    const SliceDecisions* decisions;  // may be null
    double duration, begin, end;      // the step's, and the slice's span
    double reach, fit;
    const UniformGrid* grid;
};

// What it adds up, and where it lists the paths that fit no cell whole (a
// few, read again by the pieces' passes instead of every particle's mark).
struct CountTally {
    std::size_t counted = 0;              // boxes that fit a cell
    std::uint32_t large = 0;              // paths that do not
    std::uint32_t* long_paths = nullptr;  // their particles, `large` of them so far
};

// The decided particles among `lanes` from i (bit k: particle i + k).
template <int lanes>
[[gnu::always_inline]] inline unsigned decided_lanes(const CountInput& in, std::int64_t i) {
    unsigned decided = 0;
    if (in.decisions != nullptr) {
        for (int lane = 0; lane < lanes; ++lane) {
            decided |= static_cast<unsigned>(in.decisions->decided(static_cast<std::uint32_t>(i + lane))) << lane;
        }
    }
    return decided;
}

// The count's marks and tallies of `lanes` particles from i, lane by lane
// (bit k of `binned` and `fits`, and cells[k]: particle i + k).
template <int lanes>
[[gnu::always_inline]] inline void tally_lanes(std::int64_t i, unsigned binned, unsigned fits,
                                               const std::uint32_t* cells, std::uint32_t* cell_of,
                                               std::uint32_t* counts, CountTally& tally) {
    for (int lane = 0; lane < lanes; ++lane) {
        const std::uint32_t in_slice = (binned >> lane) & 1U;
        const std::uint32_t fitting = in_slice & ((fits >> lane) & 1U);
        cell_of[i + lane] = in_slice == 0 ? absent_marker : fitting != 0 ? cells[lane] : large_marker;
        counts[cells[lane]] += fitting;
        tally.counted += fitting;
        tally.long_paths[tally.large] = static_cast<std::uint32_t>(i + lane);  // kept only if long
        tally.large += in_slice - fitting;
    }
}

// What the placement reads of a slice besides CountInput.
struct PlaceInput {
    double float_scale;                               // float_bounds()'s
    double line_position_scale, line_velocity_scale;  // GridLayout's
    bool lines;                                       // the lines are stored too
};

// Bit k set: particle i + k has a box to place (its mark is a cell).
template <int lanes>
[[gnu::always_inline]] inline unsigned placed_lanes(const std::uint32_t* cell_of, std::int64_t i) {
    unsigned placed = 0;
    for (int lane = 0; lane < lanes; ++lane) {
        placed |= static_cast<unsigned>(cell_of[i + lane] < first_piece_marker) << lane;
    }
    return placed;
}

// store(particle, record) for each placed one of `lanes` particles from i:
// bounds[b][k] and line[c][k] are particle i + k's bound b and line
// component c (read only where `with_lines`: a zero line otherwise).
template <int lanes, typename Store>
[[gnu::always_inline]] inline void store_lanes(std::int64_t i, unsigned placed, bool with_lines,
                                               const float (&bounds)[4][lanes], const float (&line)[4][lanes],
                                               Store&& store) {
    for (; placed != 0; placed &= placed - 1) {
        const int lane = std::countr_zero(placed);
        store(static_cast<std::uint32_t>(i + lane),
              BoxRecord{
                  FloatBounds{bounds[0][lane], bounds[1][lane], bounds[2][lane], bounds[3][lane]},
                  with_lines ? FloatLine{line[0][lane], line[1][lane], line[2][lane], line[3][lane]} : FloatLine{}});
    }
}

#if defined(__x86_64__)
// AVX-512 operations written with every lane's result defined (GCC 12's
// unmasked forms start from an undefined vector and warn of it).
[[gnu::target("avx512f"), gnu::always_inline]] inline __m512d lanes_min(__m512d a, __m512d b) {
    return _mm512_mask_min_pd(_mm512_setzero_pd(), 0xFF, a, b);  // a < b ? a : b
}
[[gnu::target("avx512f"), gnu::always_inline]] inline __m512d lanes_max(__m512d a, __m512d b) {
    return _mm512_mask_max_pd(_mm512_setzero_pd(), 0xFF, a, b);  // a > b ? a : b
}
[[gnu::target("avx512f"), gnu::always_inline]] inline __m256i lanes_truncated(__m512d a) {
    return _mm512_mask_cvttpd_epi32(_mm256_setzero_si256(), 0xFF, a);
}
// Eight particles' positions and velocities, from their six 64-byte lines
// (48 bytes a particle): six contiguous loads, which the processor's
// prefetchers follow through a large scene (gathers were slower there), and
// for each component one permutation of each pair of lines and two blends.
struct EightMotions {
    __m512d x, y, vx, vy;
};
[[gnu::target("avx512f"), gnu::always_inline]] inline __m512d motion_component(const __m512d* lines, long long c) {
    // Particle k's component c is double 6 k + c: particles 0 to 2 lie in lines 0 and 1, 3 and 4 in lines 2
    // and 3, 6 and 7 in lines 4 and 5; particle 5 (doubles 30 to 35) straddles lines 3 and 4.
    const bool fifth_in_second = c < 2;
    const __m512i index =
        _mm512_setr_epi64(c, c + 6, c + 12, c + 2, c + 8, fifth_in_second ? c + 14 : c - 2, c + 4, c + 10);
    const __m512d first = _mm512_permutex2var_pd(lines[0], index, lines[1]);
    const __m512d second = _mm512_permutex2var_pd(lines[2], index, lines[3]);
    const __m512d third = _mm512_permutex2var_pd(lines[4], index, lines[5]);
    const __mmask8 from_second = fifth_in_second ? 0x38 : 0x18;
    const __mmask8 from_third = fifth_in_second ? 0xC0 : 0xE0;
    return _mm512_mask_blend_pd(from_third, _mm512_mask_blend_pd(from_second, first, second), third);
}
[[gnu::target("avx512f"), gnu::always_inline]] inline EightMotions eight_motions(const Particle* eight) {
    static_assert(sizeof(Particle) == 6 * sizeof(double), "position, velocity, two counters");
    const double* at = &eight->position.x();
    const __m512d lines[6] = {_mm512_loadu_pd(at),      _mm512_loadu_pd(at + 8),  _mm512_loadu_pd(at + 16),
                              _mm512_loadu_pd(at + 24), _mm512_loadu_pd(at + 32), _mm512_loadu_pd(at + 40)};
    return {motion_component(lines, 0), motion_component(lines, 1), motion_component(lines, 2),
            motion_component(lines, 3)};
}

// Eight particles' paths in a slice: sweep_end() and swept_bounds() in
// lanes, the scalar code's operations on the same doubles (std::min(from,
// to) is (to < from ? to : from), as lanes_min(to, from); std::max likewise).
struct EightPaths {
    EightMotions motion;
    __m512d sweep_end;
    __m512d min_x, min_y, max_x, max_y;
};
[[gnu::target("avx512f"), gnu::always_inline]] inline EightPaths eight_paths(const CountInput& in, std::int64_t i) {
    EightPaths paths;
    paths.motion = eight_motions(in.particles + i);
    const auto& [x, y, vx, vy] = paths.motion;
    const __m512d begin = _mm512_set1_pd(in.begin);
    const __m512d reach = _mm512_set1_pd(in.reach);
    paths.sweep_end = lanes_min(_mm512_loadu_pd(in.wall_time + i), _mm512_set1_pd(in.duration));
    const __m512d path_end = lanes_min(paths.sweep_end, _mm512_set1_pd(in.end));
    const __m512d from_x = _mm512_add_pd(x, _mm512_mul_pd(vx, begin));
    const __m512d from_y = _mm512_add_pd(y, _mm512_mul_pd(vy, begin));
    const __m512d to_x = _mm512_add_pd(x, _mm512_mul_pd(vx, path_end));
    const __m512d to_y = _mm512_add_pd(y, _mm512_mul_pd(vy, path_end));
    paths.min_x = _mm512_sub_pd(lanes_min(to_x, from_x), reach);
    paths.min_y = _mm512_sub_pd(lanes_min(to_y, from_y), reach);
    paths.max_x = _mm512_add_pd(lanes_max(to_x, from_x), reach);
    paths.max_y = _mm512_add_pd(lanes_max(to_y, from_y), reach);
    return paths;
}

// tally_lanes<8>() in AVX-512 lanes: the eight marks in one store, the long
// paths' particles compress-stored, and the counts added lane by lane
// (neighbours in storage often share a cell, so a scatter would not do).
[[gnu::target("avx512f"), gnu::always_inline]] inline void tally_eight(std::int64_t i, unsigned binned, unsigned fits,
                                                                       __m256i cells, std::uint32_t* cell_of,
                                                                       std::uint32_t* counts, CountTally& tally) {
    const auto in_slice = static_cast<__mmask16>(binned & 0xFFU);
    const auto fitting = static_cast<__mmask16>(binned & fits & 0xFFU);
    const auto long_path = static_cast<__mmask16>(in_slice & ~fitting);
    const __m512i cells_wide = _mm512_castsi256_si512(cells);  // lanes 8 to 15 undefined, and masked off
    const __m512i marks =
        _mm512_mask_blend_epi32(fitting,
                                _mm512_mask_blend_epi32(in_slice, _mm512_set1_epi32(static_cast<int>(absent_marker)),
                                                        _mm512_set1_epi32(static_cast<int>(large_marker))),
                                cells_wide);
    _mm512_mask_storeu_epi32(cell_of + i, 0xFF, marks);
    const __m512i particles = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(i)),
                                               _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 0, 0, 0, 0, 0, 0, 0, 0));
    _mm512_mask_compressstoreu_epi32(tally.long_paths + tally.large, long_path, particles);
    alignas(32) std::uint32_t cell[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(cell), cells);
    for (int lane = 0; lane < 8; ++lane) counts[cell[lane]] += (fitting >> lane) & 1U;
    const auto fitting_count = static_cast<unsigned>(std::popcount(static_cast<unsigned>(fitting)));
    tally.counted += fitting_count;
    tally.large += static_cast<unsigned>(std::popcount(static_cast<unsigned>(in_slice))) - fitting_count;
}

// The count's loop over particles [first, last), eight at a time in AVX-512
// lanes (the rest one at a time by `one`): whether each is binned, its
// path's box, whether that fits a cell, and the cell. Every lane carries out
// the scalar code's operations on the same doubles (selects where it takes
// std::min and std::max, the same clamps as UniformGrid::column_of()), so
// the cells are the ones the placement computes again. The tallies and the
// marks are written lane by lane.
template <typename CountOne>
[[gnu::target("avx512f")]] void count_paths_eight(const CountInput& in, std::int64_t first, std::int64_t last,
                                                  std::uint32_t* cell_of, std::uint32_t* counts, CountTally& tally,
                                                  CountOne&& one) {
    const __m512d begin = _mm512_set1_pd(in.begin);
    const __m512d fit = _mm512_set1_pd(in.fit);
    const __m512d zero = _mm512_setzero_pd();
    const __m512d inverse_cell = _mm512_set1_pd(1.0 / in.grid->cell_size());
    const __m512d last_column = _mm512_set1_pd(static_cast<double>(in.grid->per_side() - 1));
    const __m256i side = _mm256_set1_epi32(in.grid->per_side());
    CountTally local = tally;  // in registers: a store to the marks or counts could otherwise be to its fields
    std::int64_t i = first;
    for (; i + 8 <= last; i += 8) {
        const EightPaths paths = eight_paths(in, i);
        // SliceSpan::holds_path(), and the decisions.
        const unsigned binned = _mm512_cmp_pd_mask(paths.sweep_end, zero, _CMP_GT_OQ) &
                                _mm512_cmp_pd_mask(paths.sweep_end, begin, _CMP_NLT_UQ);
        const __mmask8 fits = _mm512_cmp_pd_mask(_mm512_sub_pd(paths.max_x, paths.min_x), fit, _CMP_LE_OQ) &
                              _mm512_cmp_pd_mask(_mm512_sub_pd(paths.max_y, paths.min_y), fit, _CMP_LE_OQ);
        // column_of(): 0 unless above 0, the last column from per_side on, else truncated.
        const __m256i column =
            lanes_truncated(lanes_min(lanes_max(_mm512_mul_pd(paths.min_x, inverse_cell), zero), last_column));
        const __m256i row =
            lanes_truncated(lanes_min(lanes_max(_mm512_mul_pd(paths.min_y, inverse_cell), zero), last_column));
        const __m256i cells = _mm256_add_epi32(_mm256_mullo_epi32(row, side), column);
        tally_eight(i, binned & ~decided_lanes<8>(in, i), fits, cells, cell_of, counts, local);
    }
    tally = local;
    for (; i < last; ++i) one(i);
}

// float_at_most() (or, with `at_least`, float_at_least()) of each lane: the
// same operations, selects for its branches.
template <bool at_least>
[[gnu::target("avx512f"), gnu::always_inline]] inline __m256 lanes_rounded_outwards(__m512d value) {
    const __m512d largest = _mm512_set1_pd(std::numeric_limits<float>::max());
    const __m512d step =
        _mm512_add_pd(_mm512_mul_pd(_mm512_abs_pd(value), _mm512_set1_pd(0x1p-20)), _mm512_set1_pd(1e-37));
    const __m512d moved = at_least ? _mm512_add_pd(value, step) : _mm512_sub_pd(value, step);
    const __m512d negative_largest = _mm512_set1_pd(-std::numeric_limits<float>::max());
    const __m512d clamped = lanes_min(lanes_max(moved, negative_largest), largest);
    const __mmask8 beyond = at_least ? _mm512_cmp_pd_mask(moved, largest, _CMP_GT_OQ)
                                     : _mm512_cmp_pd_mask(moved, negative_largest, _CMP_LT_OQ);
    // Infinity in double converts to infinity in float.
    const double infinity =
        at_least ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    return _mm512_mask_cvtpd_ps(_mm256_setzero_ps(), 0xFF,
                                _mm512_mask_blend_pd(beyond, clamped, _mm512_set1_pd(infinity)));
}

// The placement's loop over particles [first, last) whose mark is a cell,
// eight at a time in AVX-512 lanes: each path's box (eight_paths(), as the
// count computes it), its float bounds and its line turned into records,
// then each stored at its place lane by lane by `store(particle, record)`
// (the last few one at a time by `one`).
template <typename Store, typename PlaceOne>
[[gnu::target("avx512f")]] void place_paths_eight(const CountInput& in, const PlaceInput& place, std::int64_t first,
                                                  std::int64_t last, const std::uint32_t* cell_of, Store&& store,
                                                  PlaceOne&& one) {
    const __m512d float_scale = _mm512_set1_pd(place.float_scale);
    const __m512d position_scale = _mm512_set1_pd(place.line_position_scale);
    const __m512d velocity_scale = _mm512_set1_pd(place.line_velocity_scale);
    std::int64_t i = first;
    for (; i + 8 <= last; i += 8) {
        const unsigned placed = placed_lanes<8>(cell_of, i);
        if (placed == 0) continue;
        const EightPaths paths = eight_paths(in, i);
        const auto& [x, y, vx, vy] = paths.motion;
        __m512d min_x = paths.min_x;
        __m512d min_y = paths.min_y;
        __m512d max_x = paths.max_x;
        __m512d max_y = paths.max_y;
        if (place.float_scale != 1.0) {  // float_bounds(): the same way for every box of a step
            min_x = _mm512_mul_pd(min_x, float_scale);
            min_y = _mm512_mul_pd(min_y, float_scale);
            max_x = _mm512_mul_pd(max_x, float_scale);
            max_y = _mm512_mul_pd(max_y, float_scale);
        }
        // The eight fields of each lane, turned into the lanes' records.
        __m256 fields[8] = {lanes_rounded_outwards<false>(min_x),
                            lanes_rounded_outwards<false>(min_y),
                            lanes_rounded_outwards<true>(max_x),
                            lanes_rounded_outwards<true>(max_y),
                            _mm256_setzero_ps(),
                            _mm256_setzero_ps(),
                            _mm256_setzero_ps(),
                            _mm256_setzero_ps()};
        if (place.lines) {  // float_line()
            fields[4] = _mm512_mask_cvtpd_ps(_mm256_setzero_ps(), 0xFF, _mm512_mul_pd(x, position_scale));
            fields[5] = _mm512_mask_cvtpd_ps(_mm256_setzero_ps(), 0xFF, _mm512_mul_pd(y, position_scale));
            fields[6] = _mm512_mask_cvtpd_ps(_mm256_setzero_ps(), 0xFF, _mm512_mul_pd(vx, velocity_scale));
            fields[7] = _mm512_mask_cvtpd_ps(_mm256_setzero_ps(), 0xFF, _mm512_mul_pd(vy, velocity_scale));
        }
        __m256 lane_records[8];
        transpose_eight(fields, lane_records);
        alignas(32) BoxRecord records[8];
        for (int lane = 0; lane < 8; ++lane)
            _mm256_store_ps(reinterpret_cast<float*>(records + lane), lane_records[lane]);
        for (unsigned left = placed; left != 0; left &= left - 1) {
            const int lane = std::countr_zero(left);
            store(static_cast<std::uint32_t>(i + lane), records[lane]);
        }
    }
    for (; i < last; ++i) one(i);
}

// The same count and placement four paths at a time in AVX2 lanes, for
// processors without AVX-512: the same operations on the same doubles
// (_mm256_min_pd(a, b) is a < b ? a : b, as lanes_min()).
struct FourMotions {
    __m256d x, y, vx, vy;
};
// Four particles' positions and velocities: each particle's four doubles in
// one load, turned into rows by two unpacks and two lane swaps a pair.
[[gnu::target("avx2"), gnu::always_inline]] inline FourMotions four_motions(const Particle* four) {
    const double* at = &four->position.x();
    const __m256d first = _mm256_loadu_pd(at);  // x0 y0 vx0 vy0
    const __m256d second = _mm256_loadu_pd(at + 6);
    const __m256d third = _mm256_loadu_pd(at + 12);
    const __m256d fourth = _mm256_loadu_pd(at + 18);
    const __m256d xs_low = _mm256_unpacklo_pd(first, second);  // x0 x1 vx0 vx1
    const __m256d ys_low = _mm256_unpackhi_pd(first, second);  // y0 y1 vy0 vy1
    const __m256d xs_high = _mm256_unpacklo_pd(third, fourth);
    const __m256d ys_high = _mm256_unpackhi_pd(third, fourth);
    return {_mm256_permute2f128_pd(xs_low, xs_high, 0x20), _mm256_permute2f128_pd(ys_low, ys_high, 0x20),
            _mm256_permute2f128_pd(xs_low, xs_high, 0x31), _mm256_permute2f128_pd(ys_low, ys_high, 0x31)};
}

struct FourPaths {
    FourMotions motion;
    __m256d sweep_end;
    __m256d min_x, min_y, max_x, max_y;
};
[[gnu::target("avx2"), gnu::always_inline]] inline FourPaths four_paths(const CountInput& in, std::int64_t i) {
    FourPaths paths;
    paths.motion = four_motions(in.particles + i);
    const auto& [x, y, vx, vy] = paths.motion;
    const __m256d begin = _mm256_set1_pd(in.begin);
    const __m256d reach = _mm256_set1_pd(in.reach);
    paths.sweep_end = _mm256_min_pd(_mm256_loadu_pd(in.wall_time + i), _mm256_set1_pd(in.duration));
    const __m256d path_end = _mm256_min_pd(paths.sweep_end, _mm256_set1_pd(in.end));
    const __m256d from_x = _mm256_add_pd(x, _mm256_mul_pd(vx, begin));
    const __m256d from_y = _mm256_add_pd(y, _mm256_mul_pd(vy, begin));
    const __m256d to_x = _mm256_add_pd(x, _mm256_mul_pd(vx, path_end));
    const __m256d to_y = _mm256_add_pd(y, _mm256_mul_pd(vy, path_end));
    paths.min_x = _mm256_sub_pd(_mm256_min_pd(to_x, from_x), reach);
    paths.min_y = _mm256_sub_pd(_mm256_min_pd(to_y, from_y), reach);
    paths.max_x = _mm256_add_pd(_mm256_max_pd(to_x, from_x), reach);
    paths.max_y = _mm256_add_pd(_mm256_max_pd(to_y, from_y), reach);
    return paths;
}

// float_at_most() (or, with `at_least`, float_at_least()) of each lane, as lanes_rounded_outwards().
template <bool at_least>
[[gnu::target("avx2"), gnu::always_inline]] inline __m128 four_rounded_outwards(__m256d value) {
    const __m256d largest = _mm256_set1_pd(std::numeric_limits<float>::max());
    const __m256d negative_largest = _mm256_set1_pd(-std::numeric_limits<float>::max());
    const __m256d magnitude = _mm256_andnot_pd(_mm256_set1_pd(-0.0), value);
    const __m256d step = _mm256_add_pd(_mm256_mul_pd(magnitude, _mm256_set1_pd(0x1p-20)), _mm256_set1_pd(1e-37));
    const __m256d moved = at_least ? _mm256_add_pd(value, step) : _mm256_sub_pd(value, step);
    const __m256d clamped = _mm256_min_pd(_mm256_max_pd(moved, negative_largest), largest);
    const __m256d beyond =
        at_least ? _mm256_cmp_pd(moved, largest, _CMP_GT_OQ) : _mm256_cmp_pd(moved, negative_largest, _CMP_LT_OQ);
    const double infinity =
        at_least ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    return _mm256_cvtpd_ps(_mm256_blendv_pd(clamped, _mm256_set1_pd(infinity), beyond));
}

template <typename CountOne>
[[gnu::target("avx2")]] void count_paths_four(const CountInput& in, std::int64_t first, std::int64_t last,
                                              std::uint32_t* cell_of, std::uint32_t* counts, CountTally& tally,
                                              CountOne&& one) {
    const __m256d begin = _mm256_set1_pd(in.begin);
    const __m256d fit = _mm256_set1_pd(in.fit);
    const __m256d zero = _mm256_setzero_pd();
    const __m256d inverse_cell = _mm256_set1_pd(1.0 / in.grid->cell_size());
    const __m256d last_column = _mm256_set1_pd(static_cast<double>(in.grid->per_side() - 1));
    const __m128i side = _mm_set1_epi32(in.grid->per_side());
    CountTally local = tally;  // in registers, as in count_paths_eight()
    std::int64_t i = first;
    for (; i + 4 <= last; i += 4) {
        const FourPaths paths = four_paths(in, i);
        const auto binned = static_cast<unsigned>(_mm256_movemask_pd(_mm256_and_pd(
            _mm256_cmp_pd(paths.sweep_end, zero, _CMP_GT_OQ), _mm256_cmp_pd(paths.sweep_end, begin, _CMP_NLT_UQ))));
        const auto fits = static_cast<unsigned>(
            _mm256_movemask_pd(_mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(paths.max_x, paths.min_x), fit, _CMP_LE_OQ),
                                             _mm256_cmp_pd(_mm256_sub_pd(paths.max_y, paths.min_y), fit, _CMP_LE_OQ))));
        const __m128i column = _mm256_cvttpd_epi32(
            _mm256_min_pd(_mm256_max_pd(_mm256_mul_pd(paths.min_x, inverse_cell), zero), last_column));
        const __m128i row = _mm256_cvttpd_epi32(
            _mm256_min_pd(_mm256_max_pd(_mm256_mul_pd(paths.min_y, inverse_cell), zero), last_column));
        alignas(16) std::uint32_t cells[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(cells), _mm_add_epi32(_mm_mullo_epi32(row, side), column));
        tally_lanes<4>(i, binned & ~decided_lanes<4>(in, i), fits, cells, cell_of, counts, local);
    }
    tally = local;
    for (; i < last; ++i) one(i);
}

template <typename Store, typename PlaceOne>
[[gnu::target("avx2")]] void place_paths_four(const CountInput& in, const PlaceInput& place, std::int64_t first,
                                              std::int64_t last, const std::uint32_t* cell_of, Store&& store,
                                              PlaceOne&& one) {
    const __m256d float_scale = _mm256_set1_pd(place.float_scale);
    const __m256d position_scale = _mm256_set1_pd(place.line_position_scale);
    const __m256d velocity_scale = _mm256_set1_pd(place.line_velocity_scale);
    std::int64_t i = first;
    for (; i + 4 <= last; i += 4) {
        const unsigned placed = placed_lanes<4>(cell_of, i);
        if (placed == 0) continue;
        const FourPaths paths = four_paths(in, i);
        const auto& [x, y, vx, vy] = paths.motion;
        __m256d min_x = paths.min_x;
        __m256d min_y = paths.min_y;
        __m256d max_x = paths.max_x;
        __m256d max_y = paths.max_y;
        if (place.float_scale != 1.0) {  // float_bounds(): the same way for every box of a step
            min_x = _mm256_mul_pd(min_x, float_scale);
            min_y = _mm256_mul_pd(min_y, float_scale);
            max_x = _mm256_mul_pd(max_x, float_scale);
            max_y = _mm256_mul_pd(max_y, float_scale);
        }
        alignas(16) float bounds[4][4];
        _mm_store_ps(bounds[0], four_rounded_outwards<false>(min_x));
        _mm_store_ps(bounds[1], four_rounded_outwards<false>(min_y));
        _mm_store_ps(bounds[2], four_rounded_outwards<true>(max_x));
        _mm_store_ps(bounds[3], four_rounded_outwards<true>(max_y));
        alignas(16) float line[4][4];
        if (place.lines) {  // float_line()
            _mm_store_ps(line[0], _mm256_cvtpd_ps(_mm256_mul_pd(x, position_scale)));
            _mm_store_ps(line[1], _mm256_cvtpd_ps(_mm256_mul_pd(y, position_scale)));
            _mm_store_ps(line[2], _mm256_cvtpd_ps(_mm256_mul_pd(vx, velocity_scale)));
            _mm_store_ps(line[3], _mm256_cvtpd_ps(_mm256_mul_pd(vy, velocity_scale)));
        }
        store_lanes<4>(i, placed, place.lines, bounds, line, store);
    }
    for (; i < last; ++i) one(i);
}
#endif

}  // namespace particlesim::grid_binning
