// The exact engine's calendar queues, linked and in two tiers, against a
// brute-force minimum, over random schedules like the engine's: times never
// go back, many ties, events that never happen, bursts far in the future, and
// a window rebuilt often; at time scales from subnormal spreads (bucket
// widths below the smallest normal double) to 1e300.

#include "check.hpp"

#include "core/random.hpp"
#include "exact/ladder_calendar.hpp"
#include "exact/linked_calendar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using particlesim::Event;
using particlesim::EventKind;
using particlesim::LadderCalendar;
using particlesim::LinkedCalendar;

namespace {

constexpr double never = std::numeric_limits<double>::infinity();

double delay(particlesim::SplitMix64& rng, double scale) {
    switch (rng.next() % 6) {
    case 0: return 0.0;                                          // a tie with the present
    case 1: return never;                                        // nothing predicted
    case 2: return scale * 1e6 * rng.uniform();                  // far in the future
    case 3: return scale * static_cast<double>(rng.next() % 4);  // ties on a coarse grid
    default: return scale * rng.uniform();
    }
}

template <typename Calendar>
void matches_brute_force(std::uint32_t owners, std::uint64_t seed, int operations, double scale = 1.0) {
    particlesim::SplitMix64 rng(seed);
    std::vector<Event> events(owners, Event{never, EventKind::cell_crossing, 0, 0});
    Calendar calendar(owners, events[0]);
    const auto random_event = [&](double now) {
        const auto kind = static_cast<EventKind>(rng.next() % 3);
        return Event{now + delay(rng, scale), kind, static_cast<std::uint32_t>(rng.next() % 8),
                     static_cast<std::uint32_t>(rng.next() % 8)};
    };
    for (std::uint32_t owner = 0; owner < owners; ++owner) {
        events[owner] = random_event(0.0);
        calendar.replace(owner, events[owner]);
    }
    int mismatches = 0;
    for (int k = 0; k < operations; ++k) {
        const Event expected = *std::min_element(events.begin(), events.end());
        const std::uint32_t owner = calendar.earliest_owner();
        const Event got = calendar.earliest();
        const bool same = !(got < expected) && !(expected < got) && !(events[owner] < got) && !(got < events[owner]);
        mismatches += same ? 0 : 1;
        const double now = got.time == never ? 0.0 : got.time;
        // The engine replaces the earliest entry and, sometimes, a partner's.
        events[owner] = random_event(now);
        calendar.replace(owner, events[owner]);
        if (rng.next() % 2 == 0) {
            const auto other = static_cast<std::uint32_t>(rng.next() % owners);
            events[other] = random_event(now);
            calendar.replace(other, events[other]);
        }
    }
    CHECK_EQ(mismatches, 0);
}

// The look ahead (the engine's prefetching) visits each entry at most once
// while it stays in the queue unchanged, and nearly every entry before it
// comes up, in a schedule like a large engine's: most events many buckets
// ahead, some never, a partner's entry replaced now and then.
void look_ahead_visits_each_coming_entry_once(std::uint32_t owners, std::uint32_t ahead, std::uint64_t seed) {
    particlesim::SplitMix64 rng(seed);
    LadderCalendar calendar(owners, Event{never, EventKind::wall, 0, 0});
    std::vector<std::uint32_t> version(owners, 0);
    std::vector<std::uint32_t> visited_version(owners, ~0U);
    const auto schedule = [&](std::uint32_t owner, double now) {
        ++version[owner];
        const double time = rng.next() % 16 == 0 ? never : now + rng.uniform();
        calendar.replace(owner, Event{time, EventKind::wall, owner, 0});
    };
    for (std::uint32_t owner = 0; owner < owners; ++owner) schedule(owner, 0.0);
    LadderCalendar::LookAhead look{ahead};
    int taken = 0;
    int visited_before_taken = 0;
    int visited_twice = 0;
    int strays = 0;
    for (int k = 0; k < 20 * static_cast<int>(owners); ++k) {
        const std::uint32_t owner = calendar.earliest_owner();
        if (calendar.earliest().time == never) break;
        calendar.for_each_coming(look, [&](std::uint32_t visited) {
            if (visited >= owners) {
                ++strays;
                return;
            }
            visited_twice += visited_version[visited] == version[visited] ? 1 : 0;
            visited_version[visited] = version[visited];
        });
        ++taken;
        visited_before_taken += visited_version[owner] == version[owner] ? 1 : 0;
        const double now = calendar.earliest().time;
        schedule(owner, now);
        if (rng.next() % 4 == 0) schedule(static_cast<std::uint32_t>(rng.next() % owners), now);
    }
    CHECK_EQ(strays, 0);
    CHECK_EQ(visited_twice, 0);
    CHECK(taken > 10 * static_cast<int>(owners));
    CHECK(visited_before_taken > taken / 100 * 99);
}

// The window's start and width read from a sample of the times: the start is
// the earliest of all of them, never only the sample's; up to sample_size
// entries the width is the exact quantile's; beyond, within a few percent.
void window_from_a_sample() {
    particlesim::SplitMix64 rng(11);
    for (const std::size_t owners : {1UL, 3UL, 4096UL, 4097UL, 100000UL}) {
        std::vector<double> times(owners);
        for (double& time : times) time = rng.next() % 5 == 0 ? never : 1.0 + 7.0 * rng.uniform();
        times[owners - 1] = 0.5;  // the earliest, last: the sample need not hold it
        const particlesim::CalendarWindow window(static_cast<std::uint32_t>(owners));
        std::vector<double> sample;
        const particlesim::CalendarWindow::Times read = particlesim::CalendarWindow::read_times(
            owners, [&](std::size_t k) { return times[k]; }, sample);
        std::vector<double> finite;
        for (const double time : times) {
            if (time != never) finite.push_back(time);
        }
        CHECK_EQ(read.finite, finite.size());
        CHECK(read.earliest == 0.5);
        CHECK(sample.size() <= particlesim::CalendarWindow::sample_size);
        const particlesim::CalendarWindow::Start start = window.start_for(read, sample);
        CHECK(start.base == 0.5);
        // The exact width: the earliest filled_by_half-th time's spread over filled_by_half buckets.
        std::sort(finite.begin(), finite.end());
        const std::size_t rank = std::min<std::size_t>(finite.size() - 1, window.filled_by_half);
        const double spread = finite[rank] - 0.5;  // zero with a single time: then a width of 1e-12 of it
        const double exact_width = spread > 0.0 ? spread / window.filled_by_half : 0.5e-12;
        if (finite.size() <= particlesim::CalendarWindow::sample_size) {
            CHECK(start.buckets_per_time == 1.0 / exact_width);
        } else {
            CHECK(std::abs(exact_width * start.buckets_per_time - 1.0) < 0.05);
        }
    }
}

template <typename Calendar>
void all_never() {
    Calendar calendar(5, Event{never, EventKind::wall, 0, 0});
    CHECK(calendar.earliest().time == never);
    calendar.replace(3, Event{2.5, EventKind::pair, 1, 3});
    CHECK_EQ(calendar.earliest_owner(), 3U);
    calendar.replace(3, Event{never, EventKind::wall, 3, 0});
    CHECK(calendar.earliest().time == never);
    // Of entries all at `never`, the first in the rules' order.
    Calendar crossings(5, Event{never, EventKind::cell_crossing, 9, 9});
    crossings.replace(2, Event{never, EventKind::pair, 1, 4});
    CHECK_EQ(crossings.earliest_owner(), 2U);
}

template <typename Calendar>
void against_brute_force() {
    all_never<Calendar>();
    // One seed a size under the sanitizers: the minimum over 20000 owners is slow there.
    const std::uint64_t seeds = check::sanitized ? 1 : 4;
    for (const std::uint32_t owners : {1U, 2U, 7U, 100U, 5000U, 20000U}) {
        for (std::uint64_t seed = 0; seed < seeds; ++seed)
            matches_brute_force<Calendar>(owners, seed, owners < 1000 ? 20000 : 4000);
    }
    for (const double scale : {1e-320, 1e-310, 1e-300, 1e300}) {
        for (const std::uint32_t owners : {2U, 100U, 5000U}) matches_brute_force<Calendar>(owners, 7, 4000, scale);
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_event_calendar",
                      {{"linked calendar against brute-force minimum", [] { against_brute_force<LinkedCalendar>(); }},
                       {"two-tier calendar against brute-force minimum", [] { against_brute_force<LadderCalendar>(); }},
                       {"the window's start and width from a sample of the times", window_from_a_sample},
                       {"look ahead visits each coming entry once", [] {
                            for (const std::uint32_t owners : {5000U, 40000U}) {
                                for (const std::uint32_t ahead : {1U, 3U, 8U})
                                    look_ahead_visits_each_coming_entry_once(owners, ahead, owners + ahead);
                            }
                        }}});
}
