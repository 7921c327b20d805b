#pragma once
// What both calendar queues share: how many time buckets a window has, and,
// at a rebuild, where the new window starts and how wide its buckets are.
//
// The window holds at least twice the buckets that the earliest half of the
// entries fill at a rebuild (Brown's choice), and up to eight times as many
// while that is at most 65 536 buckets: on a small scene a rebuild, which
// reads every entry, then comes a quarter as often. Larger scenes were slower
// with the longer window (docs/benchmarks.md).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace particlesim {

struct CalendarWindow {
    static constexpr std::uint32_t max_stretched_buckets = 65536;

    std::uint32_t filled_by_half;  // buckets holding the earliest half of the entries after a rebuild
    std::uint32_t buckets;         // the window's

    explicit CalendarWindow(std::uint32_t owners)
        : filled_by_half(power_of_two_from(owners) / 2),
          buckets(std::max(filled_by_half * 2, std::min(filled_by_half * 8, max_stretched_buckets))) {}

    struct Start {
        double base = 0.0;              // the start time of the window's first bucket
        double buckets_per_time = 1.0;  // the inverse of a bucket's width

        // Buckets from the window's first to `time` (negative before it,
        // infinite for `never`); the bucket is its whole part.
        [[nodiscard]] double offset(double time) const { return (time - base) * buckets_per_time; }
    };
    // What a rebuild reads of the entries' times, in one pass: the earliest
    // finite time, how many are finite, and an even sample of them (every
    // k-th finite time, at most `sample_size`; all of them in a scene of up
    // to that many entries). A sample, because the width needs only a
    // quantile of the times, and selecting it among all of them took 0.02 s
    // of a million disks' rebuild; the width decides where entries are
    // listed, never which event comes first.
    static constexpr std::size_t sample_size = 4096;
    struct Times {
        double earliest = 0.0;
        std::size_t finite = 0;
    };
    template <typename TimeOf>
    [[nodiscard]] static Times read_times(std::size_t owners, TimeOf&& time_of, std::vector<double>& sample) {
        sample.clear();
        const std::size_t stride = (owners + sample_size - 1) / sample_size;
        Times times{std::numeric_limits<double>::infinity(), 0};
        for (std::size_t owner = 0; owner < owners; ++owner) {
            const double time = time_of(owner);
            if (!(time < std::numeric_limits<double>::infinity())) continue;
            times.earliest = std::min(times.earliest, time);
            if (times.finite++ % stride == 0) sample.push_back(time);
        }
        return times;
    }

    // From read_times() (at least one finite time; the sample reordered):
    // about one entry a bucket over the first filled_by_half buckets; a
    // positive width even when many events share one instant, and one whose
    // inverse is finite. Bucket indices are then a product instead of a
    // quotient: either is monotonic in time, and that is all the order of
    // events needs.
    [[nodiscard]] Start start_for(const Times& times, std::vector<double>& sample) const {
        const double base = times.earliest;
        const std::size_t rank = std::min<std::size_t>(times.finite - 1, filled_by_half);  // among all the times
        const std::size_t in_sample = std::min(sample.size() - 1, rank * sample.size() / times.finite);
        std::nth_element(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(in_sample), sample.end());
        const double spread = sample[in_sample] - base;
        const double width = spread > 0.0 ? spread / static_cast<double>(filled_by_half) : std::abs(base) * 1e-12;
        return {base, 1.0 / std::max(width, 1e-300)};
    }

private:
    static std::uint32_t power_of_two_from(std::uint32_t owners) {
        std::uint32_t count = 16;
        while (count < owners && count < (1U << 30)) count *= 2;
        return count;
    }
};

}  // namespace particlesim
