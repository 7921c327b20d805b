#pragma once
// The exact engine's priority queue of predicted events. Events are never
// removed when a prediction goes stale; each carries the collision counts
// ("versions") of its particles when predicted, and a popped event whose
// particles have collided since is skipped. Stale events are swept out when
// they pile up, so memory stays O(live events).

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
    std::uint32_t version_i = 0;
    std::uint32_t version_j = 0;

    // The total order of rules.md, (t, kind, i, j).
    friend bool operator<(const Event& a, const Event& b) {
        return std::tie(a.time, a.kind, a.i, a.j) < std::tie(b.time, b.kind, b.i, b.j);
    }
};

class EventQueue {
public:
    [[nodiscard]] bool empty() const { return heap_.empty(); }
    [[nodiscard]] std::size_t size() const { return heap_.size(); }
    [[nodiscard]] const Event& earliest() const { return heap_.front(); }

    void push(const Event& event) {
        heap_.push_back(event);
        std::push_heap(heap_.begin(), heap_.end(), later);
    }
    Event pop() {
        std::pop_heap(heap_.begin(), heap_.end(), later);
        const Event event = heap_.back();
        heap_.pop_back();
        return event;
    }
    // Removes every event `is_stale` names once the queue has doubled since
    // the last sweep: amortised O(1) per push.
    template <typename IsStale>
    void sweep_if_grown(IsStale&& is_stale) {
        if (heap_.size() < sweep_at_) return;
        std::erase_if(heap_, is_stale);
        std::make_heap(heap_.begin(), heap_.end(), later);
        sweep_at_ = 2 * heap_.size() + min_sweep_size;
    }

private:
    static constexpr std::size_t min_sweep_size = 4096;
    static bool later(const Event& a, const Event& b) { return b < a; }  // a min-heap

    std::vector<Event> heap_;
    std::size_t sweep_at_ = min_sweep_size;
};

}  // namespace particlesim
