#pragma once
// The exact engine's event queue for a scene whose state fits the caches: one
// entry per particle, holding the earliest event predicted for it, in a
// calendar queue (R. Brown, CACM 1988). Entries sit in time buckets of width
// 1 / `buckets_per_time`, each a linked list; entries beyond the buckets'
// window wait in an overflow list. Replacing an entry is O(1), and finding
// the earliest scans the first non-empty bucket, which holds about one entry.
// When the window is used up, it is rebuilt from the overflow, its width
// chosen so that the next N / 2 events fill about N / 2 buckets.

#include "core/huge_page_allocator.hpp"
#include "exact/bucket_lists.hpp"
#include "exact/calendar_window.hpp"
#include "exact/event.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace particlesim {

class LinkedCalendar {
public:
    // Every owner starts with `initial`; replace() sets each.
    LinkedCalendar(std::uint32_t owners, const Event& initial)
        : window_(owners), lists_(window_.buckets + 1, owners), events_(owners, initial) {
        for (std::uint32_t owner = 0; owner < owners; ++owner) lists_.insert(owner, overflow());
        current_ = window_.buckets;  // the window is empty: the first earliest() builds it
    }

    [[nodiscard]] bool empty() const { return events_.empty(); }

    [[nodiscard]] std::uint32_t earliest_owner() {
        if (earliest_ == none) find_earliest();
        return earliest_;
    }
    [[nodiscard]] const Event& earliest() { return events_[earliest_owner()]; }
    [[nodiscard]] const Event& entry(std::uint32_t owner) const { return events_[owner]; }

    void replace(std::uint32_t owner, const Event& event) {
        events_[owner] = event;
        lists_.move(owner, bucket_of(event.time));
        if (owner == earliest_) {
            earliest_ = none;
        } else if (earliest_ != none && event < events_[earliest_]) {
            earliest_ = owner;
        }
    }

private:
    static constexpr std::uint32_t none = BucketLists::none;
    [[nodiscard]] std::uint32_t overflow() const { return window_.buckets; }

    // Never before the current bucket: time does not go back. Everything
    // waits in the overflow while the window is used up.
    [[nodiscard]] std::uint32_t bucket_of(double time) const {
        if (current_ == window_.buckets) return overflow();
        const double offset = start_.offset(time);
        if (!(offset < static_cast<double>(window_.buckets)))
            return overflow();  // also `never` and NaN-free infinities
        return std::max(current_, static_cast<std::uint32_t>(std::max(offset, 0.0)));
    }

    void find_earliest() {
        while (current_ < window_.buckets && lists_.first(current_) == none) ++current_;
        if (current_ == window_.buckets) rebuild_window();
        const std::uint32_t bucket = current_ < window_.buckets ? current_ : overflow();
        std::uint32_t best = lists_.first(bucket);
        lists_.for_each_in(bucket, [&](std::uint32_t k) {
            if (events_[k] < events_[best]) best = k;
        });
        earliest_ = best;
    }

    // Moves the overflow's earliest events into a fresh window of buckets.
    // The window is used up, so every entry is in the overflow: they are
    // read, and put in their new buckets, in owner order.
    void rebuild_window() {
        const CalendarWindow::Times times = CalendarWindow::read_times(
            events_.size(), [&](std::size_t owner) { return events_[owner].time; }, times_);
        if (times.finite == 0) return;  // nothing will ever happen: earliest is any entry, at `never`
        start_ = window_.start_for(times, times_);
        current_ = 0;
        lists_.refill_all([&](std::uint32_t owner) { return bucket_of(events_[owner].time); });
    }

    CalendarWindow window_;
    BucketLists lists_;              // owners by bucket; the last bucket is the overflow
    HugePageVector<Event> events_;   // by owner
    std::vector<double> times_;      // scratch of rebuild_window(): a sample of the times
    CalendarWindow::Start start_;    // where bucket 0 starts, and the buckets' width
    std::uint32_t current_ = 0;      // no entry lies in an earlier bucket
    std::uint32_t earliest_ = none;  // cached; none when unknown
};

}  // namespace particlesim
