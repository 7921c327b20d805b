// The float box array of the grid search: bounds that never shrink a box
// (even beyond float's range), and range scans that report exactly the boxes
// a brute force finds, whatever the range's length and alignment.

#include "check.hpp"

#include "core/random.hpp"
#include "search/float_bounds_array.hpp"

#include <algorithm>
#include <cmath>
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

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_float_bounds_array",
                      {{"float box scans", [] {
                            float_bounds_enclose_the_value();
                            touching_boxes_overlap();
                            std::uint64_t seed = 1;
                            for (const std::uint32_t count : {0U, 1U, 3U, 4U, 5U, 9U, 40U, 70U})
                                scans_report_exactly_the_overlaps(seed++, count);
                        }}});
}
