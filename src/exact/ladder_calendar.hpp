#pragma once
// The exact engine's event queue for a scene whose state outgrows the caches:
// one entry per particle, holding the earliest event predicted for it, in a
// calendar queue (R. Brown, CACM 1988) of two tiers, as in a ladder queue
// (Tang, Goh and Thng, ACM TOMACS 2005).
//
// Time is cut into buckets of width 1 / `buckets_per_time`; a window of
// buckets is cut into epochs of `epoch_buckets_` buckets. The current
// epoch's buckets hold their entries; each later epoch of the window is one
// bin, unsorted; entries beyond the window are listed nowhere, and are read
// from the owners' records when the window is rebuilt. Each bucket and bin
// is an array of (owner, serial) listings, appended to and never searched:
// a replaced entry's old listing stays behind, stale (its serial is no
// longer the owner's), and is dropped when met. So an event writes its new
// entry at the end of one of a few thousand arrays (a bin's end, or the
// current epoch's buckets), lines that stay in the caches, instead of
// unlinking and linking list nodes at random places of the whole queue, and
// finding the earliest walks an array instead of a chain of list nodes; in a
// large run each of those nodes is a miss to memory. An epoch's bin is spread
// into the buckets when the epoch begins, in one pass whose reads are fetched
// ahead.
//
// The earliest entry is the first in the rules' order in the first non-empty
// bucket, which holds about one live entry. When the window is used up, it
// is rebuilt from the owners' records, its width chosen so that the next N / 2
// events fill about N / 2 buckets.

#include "core/assert.hpp"
#include "core/huge_page_allocator.hpp"
#include "core/prefetch.hpp"
#include "exact/calendar_window.hpp"
#include "exact/event.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace particlesim {

class LadderCalendar {
public:
    // Every owner starts with `initial`; replace() sets each.
    LadderCalendar(std::uint32_t owners, const Event& initial)
        : window_(owners),
          epoch_buckets_(std::min(window_.buckets, max_epoch_buckets)),
          epoch_shift_(std::countr_zero(epoch_buckets_)),
          epochs_(window_.buckets / epoch_buckets_),
          buckets_(epoch_buckets_),
          bins_(epochs_),
          owners_(owners, Owned{initial, 0}) {
        epoch_ = epochs_;  // the window is used up: the first earliest() builds it
    }

    [[nodiscard]] bool empty() const { return owners_.empty(); }

    [[nodiscard]] std::uint32_t earliest_owner() {
        if (earliest_ == none) find_earliest();
        return earliest_;
    }
    [[nodiscard]] const Event& earliest() { return owners_[earliest_owner()].event; }

    // A look at the events to come, for prefetching: for_each_coming()
    // visits the owners listed in each bucket of the current epoch once,
    // when the bucket comes within `ahead` buckets of the current one; after
    // a jump over many empty buckets, or into a new epoch, only the nearest
    // few. Stale listings are passed over, unless `stale_too`: a look that
    // fetches the entries themselves would otherwise wait for each to arrive
    // (a miss to memory in a large run) before it could fetch the next.
    struct LookAhead {
        std::uint32_t ahead;
        bool stale_too = false;
        std::uint64_t visited_up_to = 0;  // one past the last bucket visited, counted from the window's start
    };
    template <typename Visit>
    void for_each_coming(LookAhead& look, Visit&& visit) const {
        constexpr std::uint64_t most_buckets = 4;
        if (epoch_ >= epochs_) return;
        const std::uint64_t epoch_start = std::uint64_t{epoch_} * epoch_buckets_;
        const std::uint64_t end = epoch_start + std::min(current_ + look.ahead + 1, epoch_buckets_);
        if (look.visited_up_to > end) look.visited_up_to = 0;  // a new window
        const std::uint64_t first = std::max({look.visited_up_to, end - std::min(end, most_buckets), epoch_start});
        for (std::uint64_t bucket = first; bucket < end; ++bucket) {
            for (const Listing& listing : buckets_[bucket - epoch_start]) {
                if (look.stale_too || live(listing)) visit(listing.owner);
            }
        }
        look.visited_up_to = end;
    }
    [[nodiscard]] const Event& entry(std::uint32_t owner) const { return owners_[owner].event; }
    void prefetch_entry(std::uint32_t owner) const { prefetch(&owners_[owner]); }

    void replace(std::uint32_t owner, const Event& event) {
        Owned& owned = owners_[owner];
        owned.event = event;
        ++owned.serial;
        list(owner, owned);
        if (owner == earliest_ || (earliest_ != none && !earliest_listed_)) {
            earliest_ = none;  // its listing is stale now; or none was listed: search afresh
        } else if (earliest_ != none && event < owners_[earliest_].event) {
            earliest_ = owner;  // earlier than an entry of the current bucket: listed in it
        }
    }

private:
    static constexpr std::uint32_t none = 0xffffffffU;  // below any particle count the engines accept

    // An epoch's buckets, whose ends an event may write to: few enough that
    // their lines stay in the caches (1024 to 8192 ran within noise of one
    // another at 1e6 disks).
    static constexpr std::uint32_t max_epoch_buckets = 2048;

    // An owner's entry and the serial of its latest listing; 32 bytes,
    // aligned, never across two lines.
    struct alignas(32) Owned {
        Event event;
        std::uint32_t serial = 0;
    };
    // One owner in a bucket or bin; live while its serial is the owner's.
    struct Listing {
        std::uint32_t owner;
        std::uint32_t serial;
    };

    [[nodiscard]] bool live(const Listing& listing) const { return owners_[listing.owner].serial == listing.serial; }

    // Lists the owner's entry in its bucket, or its epoch's bin; beyond the
    // window (or while the window is used up), nowhere. Never before the
    // current bucket: time does not go back.
    void list(std::uint32_t owner, const Owned& owned) {
        if (epoch_ >= epochs_) return;
        const double offset = start_.offset(owned.event.time);
        if (!(offset < static_cast<double>(window_.buckets))) return;  // also `never`
        const std::uint64_t now = std::uint64_t{epoch_} * epoch_buckets_ + current_;
        const std::uint64_t bucket = std::max(now, static_cast<std::uint64_t>(std::max(offset, 0.0)));
        const auto epoch = static_cast<std::uint32_t>(bucket >> epoch_shift_);
        const Listing listing{owner, owned.serial};
        if (epoch == epoch_) {
            buckets_[in_epoch(bucket)].push_back(listing);
        } else {
            bins_[epoch].push_back(listing);
        }
    }

    void find_earliest() {
        for (;;) {
            while (epoch_ < epochs_ && current_ < epoch_buckets_) {
                if (const std::uint32_t best = earliest_in(buckets_[current_]); best != none) {
                    earliest_ = best;
                    earliest_listed_ = true;
                    return;
                }
                ++current_;
            }
            if (epoch_ + 1 < epochs_) {
                begin_epoch(epoch_ + 1);
            } else if (!rebuild_window()) {
                // Nothing will ever happen: the first of the entries at `never`.
                earliest_ = 0;
                for (std::uint32_t owner = 1; owner < owners_.size(); ++owner) {
                    if (owners_[owner].event < owners_[earliest_].event) earliest_ = owner;
                }
                earliest_listed_ = false;
                return;
            }
        }
    }

    // The owner of a bucket's first live entry in the rules' order, or none,
    // in one pass that drops the stale listings. Of equal entries (a pair
    // event both partners hold) the last listed, as the linked buckets'
    // newest-first lists give it, so that both queues take them in the same
    // order (the same events, stale predictions included).
    std::uint32_t earliest_in(std::vector<Listing>& bucket) const {
        std::uint32_t best = none;
        std::size_t kept = 0;
        for (const Listing& listing : bucket) {
            if (!live(listing)) continue;
            if (best == none || !(owners_[best].event < owners_[listing.owner].event)) best = listing.owner;
            bucket[kept++] = listing;
        }
        bucket.resize(kept);
        return best;
    }

    // Spreads the epoch's bin into the buckets (all empty: the epoch before
    // is used up), its live listings in the order they were made.
    void begin_epoch(std::uint32_t epoch) {
        epoch_ = epoch;
        current_ = 0;
        std::vector<Listing>& bin = bins_[epoch];
        constexpr std::size_t fetch_ahead = 16;
        for (std::size_t k = 0; k < bin.size(); ++k) {
            if (k + fetch_ahead < bin.size()) prefetch(&owners_[bin[k + fetch_ahead].owner]);
            const Listing listing = bin[k];
            if (live(listing)) list_in_epoch(listing);
        }
        bin.clear();
    }

    // A bucket's place in its epoch.
    [[nodiscard]] std::size_t in_epoch(std::uint64_t bucket) const { return bucket & (epoch_buckets_ - 1); }

    // The same bucket as list() found when it put the listing in the bin
    // (it was beyond the current bucket then, so not moved forward).
    void list_in_epoch(const Listing& listing) {
        const auto bucket = static_cast<std::uint64_t>(std::max(start_.offset(owners_[listing.owner].event.time), 0.0));
        PARTICLESIM_ASSERT(bucket >> epoch_shift_ == epoch_, "a bin holds its epoch's entries");
        buckets_[in_epoch(bucket)].push_back(listing);
    }

    // A fresh window from the owners' entries, listed in owner order; false
    // when no entry has a finite time.
    bool rebuild_window() {
        epoch_ = epochs_;  // used up until the new window is made
        for (std::vector<Listing>& bucket : buckets_) bucket.clear();
        for (std::vector<Listing>& bin : bins_) bin.clear();
        const CalendarWindow::Times times = CalendarWindow::read_times(
            owners_.size(), [&](std::size_t owner) { return owners_[owner].event.time; }, times_);
        if (times.finite == 0) return false;
        start_ = window_.start_for(times, times_);
        epoch_ = 0;
        current_ = 0;
        for (std::uint32_t owner = 0; owner < owners_.size(); ++owner) list(owner, owners_[owner]);
        return true;
    }

    CalendarWindow window_;
    std::uint32_t epoch_buckets_;  // buckets an epoch
    int epoch_shift_;              // its base 2 logarithm: a bucket's epoch is a shift, not a division
    std::uint32_t epochs_;         // epochs a window (both powers of two: epochs_ x epoch_buckets_ = window_.buckets)
    std::vector<std::vector<Listing>> buckets_;  // the current epoch's
    std::vector<std::vector<Listing>> bins_;     // by epoch of the window; the current one's and those before are empty
    HugePageVector<Owned> owners_;               // by owner
    std::vector<double> times_;                  // scratch of rebuild_window(): a sample of the times
    CalendarWindow::Start start_;                // where the window's first bucket starts, and the buckets' width
    std::uint32_t epoch_ = 0;                    // the current epoch; epochs_ when the window is used up
    std::uint32_t current_ = 0;                  // the current bucket of the epoch: no entry lies in an earlier one
    std::uint32_t earliest_ = none;              // cached; none when unknown
    bool earliest_listed_ = false;               // in the current bucket; else found among entries at `never`
};

}  // namespace particlesim
