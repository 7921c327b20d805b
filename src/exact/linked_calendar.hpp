#pragma once
// The exact engine's event queue for a scene whose state fits the caches: one
// entry per particle, holding the earliest event predicted for it, in a
// calendar queue (R. Brown, CACM 1988). Entries sit in time buckets of width
// 1 / `buckets_per_time_`, each a linked list; entries beyond the buckets'
// window wait in an overflow list. Replacing an entry is O(1), and finding
// the earliest scans the first non-empty bucket, which holds about one entry.
// When the window is used up, it is rebuilt from the overflow, its width
// chosen so that the next N / 2 events fill about N / 2 buckets.

#include "core/huge_page_allocator.hpp"
#include "exact/bucket_lists.hpp"
#include "exact/event.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace particlesim {

class LinkedCalendar {
public:
    // Every owner starts with `initial`; replace() sets each.
    LinkedCalendar(std::uint32_t owners, const Event& initial)
        : filled_by_half_(bucket_count_for(owners) / 2),
          buckets_(std::max(filled_by_half_ * 2, std::min(filled_by_half_ * 8, max_stretched_window))),
          lists_(buckets_ + 1, owners),
          events_(owners, initial) {
        for (std::uint32_t owner = 0; owner < owners; ++owner) lists_.insert(owner, overflow());
        current_ = buckets_;  // the window is empty: the first earliest() builds it
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
    // The window holds at least twice the buckets that the earliest half of
    // the entries fill at a rebuild (Brown's choice), and up to eight times
    // as many while the buckets fit this many (256 KiB, in the caches): on a
    // small scene a rebuild, which reads every entry, then comes a quarter as
    // often. Larger scenes were slower with the longer window
    // (docs/benchmarks.md).
    static constexpr std::uint32_t max_stretched_window = 65536;

    static std::uint32_t bucket_count_for(std::uint32_t owners) {
        std::uint32_t count = 16;
        while (count < owners && count < (1U << 30)) count *= 2;
        return count;
    }
    [[nodiscard]] std::uint32_t overflow() const { return buckets_; }

    // Never before the current bucket: time does not go back. Everything
    // waits in the overflow while the window is used up.
    [[nodiscard]] std::uint32_t bucket_of(double time) const {
        if (current_ == buckets_) return overflow();
        const double offset = (time - base_) * buckets_per_time_;
        if (!(offset < static_cast<double>(buckets_))) return overflow();  // also `never` and NaN-free infinities
        return std::max(current_, static_cast<std::uint32_t>(std::max(offset, 0.0)));
    }

    void find_earliest() {
        while (current_ < buckets_ && lists_.first(current_) == none) ++current_;
        if (current_ == buckets_) rebuild_window();
        const std::uint32_t bucket = current_ < buckets_ ? current_ : overflow();
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
        times_.clear();
        for (const Event& event : events_) {
            if (event.time < std::numeric_limits<double>::infinity()) times_.push_back(event.time);
        }
        if (times_.empty()) return;  // nothing will ever happen: earliest is any entry, at `never`
        const auto first = std::min_element(times_.begin(), times_.end());
        base_ = *first;
        const std::size_t sample = std::min<std::size_t>(times_.size() - 1, filled_by_half_);
        std::nth_element(times_.begin(), times_.begin() + static_cast<std::ptrdiff_t>(sample), times_.end());
        const double spread = times_[sample] - base_;
        // About one entry a bucket over the first filled_by_half_ buckets; a
        // positive width even when many events share one instant, and one
        // whose inverse is finite. Bucket indices are then a product instead
        // of a quotient: either is monotonic in time, and that is all the
        // order of events needs.
        const double width = spread > 0.0 ? spread / static_cast<double>(filled_by_half_) : std::abs(base_) * 1e-12;
        buckets_per_time_ = 1.0 / std::max(width, 1e-300);
        current_ = 0;
        lists_.refill_all([&](std::uint32_t owner) { return bucket_of(events_[owner].time); });
    }

    std::uint32_t filled_by_half_;  // buckets holding the earliest half of the entries after a rebuild
    std::uint32_t buckets_;
    BucketLists lists_;              // owners by bucket; the last bucket is the overflow
    HugePageVector<Event> events_;   // by owner
    std::vector<double> times_;      // scratch of rebuild_window()
    double base_ = 0.0;              // start time of bucket 0
    double buckets_per_time_ = 1.0;  // the inverse of a bucket's width
    std::uint32_t current_ = 0;      // no entry lies in an earlier bucket
    std::uint32_t earliest_ = none;  // cached; none when unknown
};

}  // namespace particlesim
