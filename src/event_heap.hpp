#pragma once
// The exact engine's event queue: one entry per particle, holding the earliest
// event predicted for it, in an indexed 4-ary heap. A particle's entry is
// replaced in place (O(log N)) whenever its prediction changes, so the heap
// never holds more than N entries and never fills with stale events. Four
// children per node halve the depth of a binary heap and sit on adjacent
// cache lines: with 1e6 particles the heap is memory-bound.

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

namespace particlesim {

enum class EventKind : std::uint8_t {
    wall = 0,           // the same kinds and order as Collision: walls first
    pair = 1,
    cell_crossing = 2,  // bookkeeping only, changes no motion
};

struct Event {
    double time = 0.0;  // absolute, in steps since the start
    EventKind kind = EventKind::wall;
    std::uint32_t i = 0;  // the particle, or the lower index of a pair
    std::uint32_t j = 0;  // pair: the higher index; crossing: the cell entered

    // The total order of rules.md, (t, kind, i, j).
    friend bool operator<(const Event& a, const Event& b) {
        if (a.time != b.time) return a.time < b.time;
        return std::tie(a.kind, a.i, a.j) < std::tie(b.kind, b.i, b.j);
    }
};

class EventHeap {
public:
    // Every owner starts with the same event (a valid heap); replace() sets each.
    EventHeap(std::uint32_t owners, const Event& initial) : position_(owners) {
        heap_.reserve(owners);
        for (std::uint32_t owner = 0; owner < owners; ++owner) {
            heap_.push_back({initial, owner});
            position_[owner] = owner;
        }
    }

    [[nodiscard]] bool empty() const { return heap_.empty(); }
    [[nodiscard]] const Event& earliest() const { return heap_.front().event; }
    [[nodiscard]] std::uint32_t earliest_owner() const { return heap_.front().owner; }

    void replace(std::uint32_t owner, const Event& event) {
        const std::size_t at = position_[owner];
        const bool earlier = event < heap_[at].event;
        heap_[at].event = event;
        if (earlier) {
            sift_up(at);
        } else {
            sift_down(at);
        }
    }

private:
    static constexpr std::size_t arity = 4;

    struct Entry {
        Event event;
        std::uint32_t owner;
    };

    void place(std::size_t at, const Entry& entry) {
        heap_[at] = entry;
        position_[entry.owner] = static_cast<std::uint32_t>(at);
    }
    void sift_up(std::size_t at) {
        const Entry moving = heap_[at];
        while (at > 0) {
            const std::size_t parent = (at - 1) / arity;
            if (!(moving.event < heap_[parent].event)) break;
            place(at, heap_[parent]);
            at = parent;
        }
        place(at, moving);
    }
    void sift_down(std::size_t at) {
        const Entry moving = heap_[at];
        const std::size_t size = heap_.size();
        for (;;) {
            const std::size_t first = arity * at + 1;
            if (first >= size) break;
            std::size_t child = first;
            const std::size_t last = std::min(first + arity, size);
            for (std::size_t other = first + 1; other < last; ++other) {
                if (heap_[other].event < heap_[child].event) child = other;
            }
            if (!(heap_[child].event < moving.event)) break;
            place(at, heap_[child]);
            at = child;
        }
        place(at, moving);
    }

    std::vector<Entry> heap_;
    std::vector<std::uint32_t> position_;  // of each owner in heap_
};

}  // namespace particlesim
