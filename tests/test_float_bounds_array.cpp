// The float box array of the grid search: bounds that never shrink a box
// (even beyond float's range), range scans that report exactly the boxes a
// brute force finds, whatever the range's length and alignment, and scans
// with the lines' test that keep every pair whose lines pass within reach.

#include "check.hpp"

#include "core/random.hpp"
#include "search/box_records.hpp"
#include "search/float_bounds_array.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

using namespace particlesim;

namespace {

void float_bounds_enclose_the_value() {
    SplitMix64 rng(7);
    int wrong = 0;
    for (int k = 0; k < 200000; ++k) {
        // Magnitudes from 1e-300 to 1e300, both signs, and exact zeros.
        const double magnitude = std::pow(10.0, -300.0 + 600.0 * rng.uniform());
        const double value = k % 50 == 0 ? 0.0 : (rng.next() % 2 ? magnitude : -magnitude);
        if (!(static_cast<double>(float_at_most(value)) <= value)) ++wrong;
        if (!(static_cast<double>(float_at_least(value)) >= value)) ++wrong;
    }
    CHECK_EQ(wrong, 0);
    // Tight enough to be useful: within a millionth of the value.
    CHECK(std::abs(float_at_most(20000.0) - 20000.0f) < 0.03f);
    CHECK(std::abs(float_at_least(-20000.0) + 20000.0f) < 0.03f);
    // Beyond float's range a bound opens outwards, never inwards.
    constexpr float inf = std::numeric_limits<float>::infinity();
    CHECK(float_at_most(-1e300) == -inf);
    CHECK(float_at_least(1e300) == inf);
    CHECK(float_at_most(1e300) == std::numeric_limits<float>::max());
    CHECK(float_at_least(-1e300) == -std::numeric_limits<float>::max());
}

bool overlap(const FloatBounds& p, const FloatBounds& q) {
    return p.min_x <= q.max_x && q.min_x <= p.max_x && p.min_y <= q.max_y && q.min_y <= p.max_y;
}

FloatBounds random_box(SplitMix64& rng, float extent) {
    const auto coordinate = [&] { return static_cast<float>(rng.uniform()) * extent; };
    const float x = coordinate();
    const float y = coordinate();
    return {x, y, x + coordinate() * 0.2f, y + coordinate() * 0.2f};
}

// Every range [first, last) of an array, scanned against random probes in
// blocks of each size (ranges shorter and longer than a block, ending inside
// one or at its edge), reports exactly the overlapping boxes, each once and
// in increasing order.
void scans_report_exactly_the_overlaps(std::uint64_t seed, std::uint32_t count) {
    SplitMix64 rng(seed);
    FloatBoundsArray array;
    array.resize(count);
    std::vector<FloatBounds> boxes(count);
    for (std::uint32_t m = 0; m < count; ++m) {
        boxes[m] = random_box(rng, 10.0f);
        array.set(m, boxes[m]);
    }
    // Stored boxes read back as they were set.
    int misread = 0;
    for (std::uint32_t m = 0; m < count; ++m) {
        const FloatBounds back = array[m];
        if (back.min_x != boxes[m].min_x || back.max_y != boxes[m].max_y) ++misread;
    }
    CHECK_EQ(misread, 0);

    int wrong = 0;
    int reported_total = 0;
    for (std::uint32_t first = 0; first <= count; ++first) {
        for (std::uint32_t last = first; last <= count; ++last) {
            const FloatBounds probe = random_box(rng, 10.0f);
            std::vector<std::uint32_t> expected;
            for (std::uint32_t m = first; m < last; ++m) {
                if (overlap(boxes[m], probe)) expected.push_back(m);
            }
            const auto scan_in_blocks = [&](auto block_groups, auto group_lanes) {
                std::vector<std::uint32_t> reported;
                array.for_each_overlap<block_groups(), group_lanes()>(first, last, probe,
                                                                      [&](std::uint32_t m) { reported.push_back(m); });
                if (reported != expected) ++wrong;
            };
            const auto scan_in_groups_of = [&](auto group_lanes) {
                scan_in_blocks(std::integral_constant<std::uint32_t, 1>{}, group_lanes);
                scan_in_blocks(std::integral_constant<std::uint32_t, 2>{}, group_lanes);
                scan_in_blocks(std::integral_constant<std::uint32_t, 4>{}, group_lanes);
                scan_in_blocks(std::integral_constant<std::uint32_t, FloatBoundsArray::max_block_groups>{},
                               group_lanes);
            };
            scan_in_groups_of(std::integral_constant<std::uint32_t, FloatBoundsArray::lanes>{});
            scan_in_groups_of(std::integral_constant<std::uint32_t, FloatBoundsArray::wide_lanes>{});
            reported_total += static_cast<int>(expected.size());
        }
    }
    CHECK_EQ(wrong, 0);
    // The probes are large enough that the scans have something to find.
    if (count >= 8) CHECK(reported_total > 0);
}

// Boxes that touch only at a boundary overlap (closed intervals), as in the
// double-precision test they stand for.
void touching_boxes_overlap() {
    FloatBoundsArray array;
    array.resize(5);
    array.set(0, {0.0f, 0.0f, 1.0f, 1.0f});
    array.set(1, {1.0f, 1.0f, 2.0f, 2.0f});     // touches the probe's corner
    array.set(2, {1.5f, 0.0f, 2.0f, 1.0f});     // right of the probe
    array.set(3, {-1.0f, -1.0f, -0.5f, 0.5f});  // left of the probe
    array.set(4, {0.5f, 1.0f, 0.6f, 3.0f});     // touches the probe's top edge
    std::vector<std::uint32_t> reported;
    array.for_each_overlap<1>(0, 5, {0.0f, 0.0f, 1.0f, 1.0f}, [&](std::uint32_t m) { reported.push_back(m); });
    CHECK(reported == (std::vector<std::uint32_t>{0, 1, 4}));
}

// Lane widths with their scans: four and eight everywhere (eight as two
// halves without AVX), sixteen where the processor has AVX-512.
bool has_sixteen_lanes() {
#if defined(__x86_64__)
    return __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("fma") != 0;
#else
    return false;
#endif
}

// The records' eight-lane transpose: x86-64 with AVX2.
bool has_eight_lanes() {
#if defined(__x86_64__)
    return __builtin_cpu_supports("avx2") != 0;
#else
    return false;
#endif
}

// Every range of an array of boxes with lines, scanned with the line test in
// every lane width and block size: what is reported is a box overlap, every
// overlap whose lines pass within reach (in double, before the rounding to
// float) is reported, and four and eight lanes report the same. Half the
// lines pass the probe's at reach times (1 - 2^-24): as near the edge of
// the test as a pair can come.
void line_scans_keep_every_pair_within_reach(std::uint64_t seed, std::uint32_t count) {
    SplitMix64 rng(seed);
    const double reach = 1e-3;
    const LineTerms terms = line_test_terms(1.0, 1.0, reach);
    struct Line {
        double x, y, vx, vy;
    };
    const auto random_line = [&] {
        return Line{rng.uniform(), rng.uniform(), 2.0 * rng.uniform() - 1.0, 2.0 * rng.uniform() - 1.0};
    };
    const auto to_float = [](const Line& line) {
        return FloatLine{static_cast<float>(line.x), static_cast<float>(line.y), static_cast<float>(line.vx),
                         static_cast<float>(line.vy)};
    };
    const auto within_reach = [&](const Line& a, const Line& b) {
        const double dx = b.x - a.x, dy = b.y - a.y, dvx = b.vx - a.vx, dvy = b.vy - a.vy;
        return std::abs(dx * dvy - dy * dvx) <= reach * std::sqrt(dvx * dvx + dvy * dvy);
    };
    int wrong = 0;
    int kept_within_reach = 0;
    for (std::uint32_t first = 0; first <= count; ++first) {
        for (std::uint32_t last = first; last <= count; ++last) {
            const Line probe_line = random_line();
            const FloatBounds probe = random_box(rng, 10.0f);
            FloatBoundsArray array;
            array.resize(count);
            array.resize_lines();
            std::vector<FloatBounds> boxes(count);
            std::vector<Line> lines(count);
            for (std::uint32_t m = 0; m < count; ++m) {
                boxes[m] = random_box(rng, 10.0f);
                lines[m] = random_line();
                if (m % 2 == 0) {  // through a point at reach (1 - 2^-24) from the probe's line
                    const double dvx = lines[m].vx - probe_line.vx, dvy = lines[m].vy - probe_line.vy;
                    const double norm = std::sqrt(dvx * dvx + dvy * dvy);
                    const double along = 2.0 * rng.uniform() - 1.0;
                    const double off = reach * (1.0 - 0x1p-24) / norm;
                    lines[m].x = probe_line.x + along * dvx - off * dvy;
                    lines[m].y = probe_line.y + along * dvy + off * dvx;
                }
                array.set(m, boxes[m]);
                array.set_line(m, to_float(lines[m]));
            }
            const auto scan = [&](auto block_groups, auto group_lanes) {
                std::vector<std::uint32_t> reported;
                array.for_each_close<block_groups(), group_lanes(), true>(
                    first, last, probe, to_float(probe_line), terms, [&](std::uint32_t m) { reported.push_back(m); });
                for (std::uint32_t m = first; m < last; ++m) {
                    const bool found = std::find(reported.begin(), reported.end(), m) != reported.end();
                    const bool boxes_meet = overlap(boxes[m], probe);
                    if (found && !boxes_meet) ++wrong;
                    if (boxes_meet && within_reach(lines[m], probe_line) && !found) ++wrong;
                    kept_within_reach += boxes_meet && within_reach(lines[m], probe_line) ? 1 : 0;
                }
                return reported;
            };
            const auto scans_in_groups_of = [&](auto group_lanes) {
                std::vector<std::vector<std::uint32_t>> all;
                all.push_back(scan(std::integral_constant<std::uint32_t, 1>{}, group_lanes));
                all.push_back(scan(std::integral_constant<std::uint32_t, 2>{}, group_lanes));
                // The largest block whose hits fit 64 bits.
                constexpr std::uint32_t largest =
                    std::min(FloatBoundsArray::max_block_groups, std::uint32_t{64} / decltype(group_lanes)::value);
                all.push_back(scan(std::integral_constant<std::uint32_t, largest>{}, group_lanes));
                for (const auto& reported : all) wrong += reported == all[0] ? 0 : 1;
                return all[0];
            };
            const auto four = scans_in_groups_of(std::integral_constant<std::uint32_t, FloatBoundsArray::lanes>{});
            const auto eight =
                scans_in_groups_of(std::integral_constant<std::uint32_t, FloatBoundsArray::wide_lanes>{});
            wrong += four == eight ? 0 : 1;
            if (has_sixteen_lanes())
                scans_in_groups_of(std::integral_constant<std::uint32_t, FloatBoundsArray::widest_lanes>{});
        }
    }
    CHECK_EQ(wrong, 0);
    // The pairs at the edge of reach were there to keep.
    if (count >= 8) CHECK(kept_within_reach > 0);
}

// Records placed in cell order turn into the scans' rows float for float,
// for any count (whole blocks of sixteen and a rest), on every path, and
// nothing past the count is written.
void records_turn_into_rows() {
    SplitMix64 rng(300);
    int wrong = 0;
    for (const std::uint32_t count : {0U, 1U, 15U, 16U, 17U, 33U, 100U}) {
        std::vector<BoxRecord> records(count);
        for (BoxRecord& record : records) {
            float floats[8];
            for (float& f : floats) f = static_cast<float>((rng.uniform() - 0.5) * 1e6);
            if (rng.next() % 7 == 0) floats[rng.next() % 8] = -std::numeric_limits<float>::infinity();
            std::memcpy(&record, floats, sizeof floats);
        }
        for (const int lanes : {4, 8, 16}) {
            if ((lanes == 16 && !has_sixteen_lanes()) || (lanes == 8 && !has_eight_lanes())) continue;
            constexpr float untouched = 12345.0f;
            std::vector<std::vector<float>> storage(8, std::vector<float>(count + 16, untouched));
            std::array<float*, 8> rows{};
            for (int f = 0; f < 8; ++f) rows[f] = storage[f].data();
            records_to_rows(reinterpret_cast<const std::byte*>(records.data()), count, rows, lanes);
            for (std::uint32_t k = 0; k < count; ++k) {
                float floats[8];
                std::memcpy(floats, &records[k], sizeof floats);
                for (int f = 0; f < 8; ++f)
                    wrong +=
                        std::bit_cast<std::uint32_t>(rows[f][k]) == std::bit_cast<std::uint32_t>(floats[f]) ? 0 : 1;
            }
            for (int f = 0; f < 8; ++f) {
                for (std::uint32_t k = count; k < count + 16; ++k) wrong += rows[f][k] == untouched ? 0 : 1;
            }
        }
    }
    CHECK_EQ(wrong, 0);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_float_bounds_array",
                      {{"float box scans",
                        [] {
                            float_bounds_enclose_the_value();
                            touching_boxes_overlap();
                            std::uint64_t seed = 1;
                            for (const std::uint32_t count : {0U, 1U, 3U, 4U, 5U, 9U, 40U, 70U})
                                scans_report_exactly_the_overlaps(seed++, count);
                        }},
                       {"records into rows", records_turn_into_rows},
                       {"line scans", [] {
                            std::uint64_t seed = 100;
                            for (const std::uint32_t count : {0U, 1U, 5U, 17U, 40U})
                                line_scans_keep_every_pair_within_reach(seed++, count);
                        }}});
}
