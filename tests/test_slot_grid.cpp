// The slot grid of the fast grid search: float bounds that never shrink a
// box, and exactly the overlapping pairs of a brute force, with full cells
// refusing boxes instead of losing them.

#include "check.hpp"

#include "../src/slot_grid.hpp"
#include "particlesim/random.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

using namespace particlesim;

namespace {

void float_bounds_enclose_the_value() {
    SplitMix64 rng(7);
    int wrong = 0;
    for (int k = 0; k < 200000; ++k) {
        // Magnitudes from 1e-300 to 1e36, both signs, and exact zeros.
        const double magnitude = std::pow(10.0, -300.0 + 336.0 * rng.uniform());
        const double value = k % 50 == 0 ? 0.0 : (rng.next() % 2 ? magnitude : -magnitude);
        if (!(static_cast<double>(float_at_most(value)) <= value)) ++wrong;
        if (!(static_cast<double>(float_at_least(value)) >= value)) ++wrong;
    }
    CHECK_EQ(wrong, 0);
    // Tight enough to be useful: within a millionth of the value.
    CHECK(std::abs(float_at_most(20000.0) - 20000.0f) < 0.03f);
}

struct Placed {
    int cx, cy;
    FloatBox box;
};

// Random boxes no larger than a cell, binned by their lower corner; returns
// the pairs the grid reports and, separately, the pairs a brute force finds
// among the boxes it accepted. Boxes refused go to `refused`.
void grid_finds_every_overlap_once(std::uint64_t seed, int side, int count) {
    SplitMix64 rng(seed);
    const float cell = 10.0f;
    SlotGrid grid;
    grid.reset(side);
    std::vector<Placed> accepted;
    int refused = 0;
    for (int i = 0; i < count; ++i) {
        const float x = static_cast<float>(rng.uniform()) * cell * static_cast<float>(side);
        const float y = static_cast<float>(rng.uniform()) * cell * static_cast<float>(side);
        const float w = static_cast<float>(rng.uniform()) * cell * 0.99f;
        const float h = static_cast<float>(rng.uniform()) * cell * 0.99f;
        const Placed p{std::min(static_cast<int>(x / cell), side - 1), std::min(static_cast<int>(y / cell), side - 1),
                       {x, y, x + w, y + h}};
        if (grid.insert(p.cx, p.cy, p.box, static_cast<std::uint32_t>(accepted.size()))) {
            accepted.push_back(p);
        } else {
            ++refused;
        }
    }
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> reported;
    grid.for_each_overlap([&](std::uint32_t a, std::uint32_t b) { reported.insert({std::min(a, b), std::max(a, b)}); });
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> expected;
    for (std::uint32_t a = 0; a < accepted.size(); ++a) {
        for (std::uint32_t b = a + 1; b < accepted.size(); ++b) {
            const FloatBox& p = accepted[a].box;
            const FloatBox& q = accepted[b].box;
            if (p.min_x <= q.max_x && q.min_x <= p.max_x && p.min_y <= q.max_y && q.min_y <= p.max_y) expected.insert({a, b});
        }
    }
    CHECK(reported == expected);
    // A crowded grid must refuse some boxes (4 slots a cell), a sparse one none.
    if (count > 4 * side * side) CHECK(refused >= count - 4 * side * side);
    if (count == 1) CHECK_EQ(refused, 0);

    // The region query finds exactly the accepted boxes in its cells that overlap.
    const FloatBox probe{12.0f, 12.0f, 31.0f, 24.0f};
    std::multiset<std::uint32_t> found;
    grid.for_each_in_region({0, 0, std::min(3, side - 1), std::min(2, side - 1)}, probe, [&](std::uint32_t id) { found.insert(id); });
    std::multiset<std::uint32_t> in_region;
    for (std::uint32_t a = 0; a < accepted.size(); ++a) {
        const Placed& p = accepted[a];
        const bool inside = p.cx <= 3 && p.cy <= 2;
        if (inside && p.box.min_x <= probe.max_x && probe.min_x <= p.box.max_x && p.box.min_y <= probe.max_y &&
            probe.min_y <= p.box.max_y) {
            in_region.insert(a);
        }
    }
    CHECK(found == in_region);

    // Cleared, the grid reports nothing and accepts as many boxes again.
    grid.clear();
    int pairs_after_clear = 0;
    grid.for_each_overlap([&](std::uint32_t, std::uint32_t) { ++pairs_after_clear; });
    CHECK_EQ(pairs_after_clear, 0);
    CHECK(grid.insert(0, 0, {0.0f, 0.0f, 1.0f, 1.0f}, 0));
    grid.clear();
}

}  // namespace

int main() {
    float_bounds_enclose_the_value();
    std::uint64_t seed = 1;
    for (const int side : {1, 2, 5, 16}) {
        for (const int count : {1, 3, side * side, 3 * side * side, 8 * side * side}) {
            grid_finds_every_overlap_once(seed++, side, count);
        }
    }
    return check::summary("test_slot_grid");
}
