#pragma once
// Items 0 .. n-1 (particles), each in one of a fixed number of buckets
// (cells), with each bucket's first two members kept in a record of its own
// and the rest, if any, in a linked list threaded through per-item places.
// A search of the 3 x 3 cells around a particle then reads their members
// from three runs of adjacent records, where a linked list (BucketLists)
// needs a dependent load for every member and one more to find the end:
// in a state far larger than the caches, a miss to memory each. In a state
// that fits the caches the linked lists are faster (smaller, and an empty
// cell costs one load either way): CellList chooses.

#include "core/huge_page_allocator.hpp"
#include "core/prefetch.hpp"

#include <cstdint>

namespace particlesim {

class CellRecords {
public:
    static constexpr std::uint32_t none = 0xffffffffU;  // below any particle count the engines accept
    // Members kept in a bucket's own record. At area fraction 0.3 a
    // diameter-wide cell holds 0.38 disks on average, two or fewer in 99 %.
    static constexpr std::uint32_t slots = 2;

    // Every item starts in no bucket; insert() places it.
    CellRecords(std::size_t buckets, std::size_t items) : records_(buckets), places_(items) {}

    [[nodiscard]] std::uint32_t bucket_of(std::uint32_t item) const { return places_[item].bucket; }

    void prefetch_record(std::uint32_t bucket) const { prefetch(&records_[bucket]); }
    void prefetch_place(std::uint32_t item) const { prefetch(&places_[item]); }
    // visit(member) for each slot of the bucket's record, `none` when empty.
    template <typename Visit>
    void for_each_slot(std::uint32_t bucket, Visit&& visit) const {
        for (const std::uint32_t member : records_[bucket].members) visit(member);
    }

    void insert(std::uint32_t item, std::uint32_t bucket) {
        Record& record = records_[bucket];
        Place& place = places_[item];
        place.bucket = bucket;
        for (std::uint32_t slot = 0; slot < slots; ++slot) {
            if (record.members[slot] == none) {
                record.members[slot] = item;
                place.slot = slot;
                return;
            }
        }
        // Full: first in the overflow list.
        place.slot = slots;
        place.previous = none;
        place.next = record.overflow;
        if (record.overflow != none) places_[record.overflow].previous = item;
        record.overflow = item;
    }

    void remove(std::uint32_t item) {
        const Place place = places_[item];
        Record& record = records_[place.bucket];
        if (place.slot == slots) {
            unlink_overflow(record, place);
            return;
        }
        // The members stay at the front of the record (so that a search
        // stops at the first empty slot): the last one fills the gap, and
        // the first of the overflow list (if any) the last slot.
        std::uint32_t last = slots - 1;
        while (record.members[last] == none) --last;
        const std::uint32_t moved = record.members[last];
        record.members[place.slot] = moved;
        places_[moved].slot = place.slot;
        record.members[last] = none;
        if (record.overflow != none) {
            const std::uint32_t promoted = record.overflow;
            unlink_overflow(record, places_[promoted]);
            record.members[last] = promoted;
            places_[promoted].slot = last;
        }
    }

    void move(std::uint32_t item, std::uint32_t bucket) {
        remove(item);
        insert(item, bucket);
    }

    // visit(item) for every item in the bucket.
    template <typename Visit>
    void for_each_in(std::uint32_t bucket, Visit&& visit) const {
        const Record& record = records_[bucket];
        for (const std::uint32_t member : record.members) {
            if (member == none) return;  // no overflow without full slots
            visit(member);
        }
        for (std::uint32_t item = record.overflow; item != none; item = places_[item].next) visit(item);
    }

private:
    struct Record {
        std::uint32_t members[slots] = {none, none};
        std::uint32_t overflow = none;  // the first of the rest
    };
    // Where an item is: its bucket and slot there (`slots` for the overflow
    // list, with its neighbours in that list).
    struct alignas(16) Place {
        std::uint32_t bucket = 0;
        std::uint32_t slot = 0;
        std::uint32_t next = none;
        std::uint32_t previous = none;
    };

    void unlink_overflow(Record& record, const Place& place) {
        if (place.previous == none) {
            record.overflow = place.next;
        } else {
            places_[place.previous].next = place.next;
        }
        if (place.next != none) places_[place.next].previous = place.previous;
    }

    HugePageVector<Record> records_;
    HugePageVector<Place> places_;  // by item
};

}  // namespace particlesim
