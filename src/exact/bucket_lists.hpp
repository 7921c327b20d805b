#pragma once
// Items 0 .. n-1, each in one of a fixed number of buckets, every bucket a
// doubly linked list threaded through per-item records: O(1) insert, remove
// and move, no allocation after construction. The exact engine's cell lists
// (particles by cell) and its linked calendar (particles by time bucket) are
// both this. An item's record may hold more than its links: the exact
// engine keeps a particle's state there, so that reading a neighbour found
// in a cell, and following the cell's list past it, read one cache line.

#include "core/huge_page_allocator.hpp"
#include "core/prefetch.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace particlesim {

// An item's links and bucket together, so that moving it reads one line of
// them instead of one in each of three arrays (each a miss to memory in a
// large exact run); 16 bytes, aligned, never across lines.
struct alignas(16) BucketLinks {
    std::uint32_t next = 0xffffffffU;  // BucketListsOf::none
    std::uint32_t previous = 0xffffffffU;
    std::uint32_t bucket = 0;
};

// Record: BucketLinks, or a struct with the same three members (which only
// the lists write) and more.
template <typename Record>
class BucketListsOf {
public:
    static constexpr std::uint32_t none = 0xffffffffU;  // below any particle count the engines accept

    // Every item starts in no bucket; insert() places it.
    BucketListsOf(std::size_t buckets, std::size_t items)
        : items_(items), heads_(buckets, Head{}), records_(items + 1) {}

    [[nodiscard]] std::uint32_t bucket_of(std::uint32_t item) const { return records_[item].bucket; }
    [[nodiscard]] std::uint32_t first(std::uint32_t bucket) const { return heads_[bucket].first; }
    [[nodiscard]] std::uint32_t second(std::uint32_t bucket) const { return heads_[bucket].second; }
    [[nodiscard]] std::uint32_t next(std::uint32_t item) const { return records_[item].next; }
    [[nodiscard]] std::uint32_t previous(std::uint32_t item) const { return records_[item].previous; }
    [[nodiscard]] Record& record(std::uint32_t item) { return records_[item]; }
    [[nodiscard]] const Record& record(std::uint32_t item) const { return records_[item]; }

    // The item's record (`none`: the spare slot's).
    void prefetch_links(std::uint32_t item) const { prefetch(&records_[slot(item)]); }
    void prefetch_head(std::uint32_t bucket) const { prefetch(&heads_[bucket]); }

    // Without branches on whether a neighbour exists (in a queue or a cell
    // list that is random, and was mispredicted half the time): a link of a
    // missing neighbour is written to a spare slot past the last item, and
    // the head is always written, with its own values when they stay.
    void insert(std::uint32_t item, std::uint32_t bucket) {
        Head& head = heads_[bucket];
        const std::uint32_t first = head.first;
        Record& own = records_[item];
        own.next = first;
        own.previous = none;
        own.bucket = bucket;
        records_[slot(first)].previous = item;
        head = {item, first};
    }
    void remove(std::uint32_t item) {
        const BucketLinks own{records_[item].next, records_[item].previous, records_[item].bucket};
        records_[slot(own.previous)].next = own.next;
        records_[slot(own.next)].previous = own.previous;
        Head& head = heads_[own.bucket];
        const bool was_first = own.previous == none;
        const bool was_second = head.second == item;
        // The item after the item's next, needed only when the item was
        // first; then, if it had no next, the first write above set the
        // spare slot's next to none, and this reads none.
        const std::uint32_t third = records_[slot(own.next)].next;
        head.second = was_first ? third : was_second ? own.next : head.second;
        head.first = was_first ? own.next : head.first;
    }
    void move(std::uint32_t item, std::uint32_t bucket) {
        remove(item);
        insert(item, bucket);
    }

    // Empties every bucket, then inserts item 0, 1, ... into bucket_for(item):
    // one pass through the per-item arrays in order, instead of a move per
    // item in the lists' order (which jumps through memory at random).
    template <typename BucketFor>
    void refill_all(BucketFor&& bucket_for) {
        std::fill(heads_.begin(), heads_.end(), Head{});
        for (std::uint32_t item = 0; item < items_; ++item) insert(item, bucket_for(item));
    }

    // Writes the bucket's items but `skipped` to out[k], out[k + 1], ...
    // and returns the k after the last; out needs room for them and one
    // more. The first two, from the head, are written whether or not an
    // item fills their places (each counted only when one does), so that the
    // buckets of a search, mostly empty or of one item at random, cost no
    // mispredicted branch and no wait for a record.
    std::size_t gather(std::uint32_t bucket, std::uint32_t skipped, std::uint32_t* out, std::size_t k) const {
        const Head head = heads_[bucket];
        out[k] = head.first;
        k += static_cast<std::size_t>((head.first != none) & (head.first != skipped));
        out[k] = head.second;
        k += static_cast<std::size_t>((head.second != none) & (head.second != skipped));
        if (head.second == none) return k;  // nearly always
        for (std::uint32_t item = records_[head.second].next; item != none; item = records_[item].next) {
            out[k] = item;
            k += static_cast<std::size_t>(item != skipped);
        }
        return k;
    }

    // visit(item) for every item in the bucket.
    template <typename Visit>
    void for_each_in(std::uint32_t bucket, Visit&& visit) const {
        for (std::uint32_t item = heads_[bucket].first; item != none; item = records_[item].next) visit(item);
    }

private:
    // The item's own slot, or the spare one for `none` (above every item).
    [[nodiscard]] std::size_t slot(std::uint32_t item) const { return std::min<std::size_t>(item, items_); }

    // A bucket's first two items (none where it has fewer): a search reads
    // both without waiting for the first's record.
    struct alignas(8) Head {
        std::uint32_t first = none;
        std::uint32_t second = none;
    };

    std::size_t items_;
    HugePageVector<Head> heads_;
    HugePageVector<Record> records_;  // one more than the items: the spare slot
};

using BucketLists = BucketListsOf<BucketLinks>;

}  // namespace particlesim
