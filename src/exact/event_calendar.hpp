#pragma once
// The exact engine's event queue: one entry per particle, holding the earliest
// event predicted for it. Two calendar queues give the same earliest entry
// (the first in the rules' order), and a scene keeps the one chosen at its
// start: linked buckets (LinkedCalendar) while the state fits the caches,
// where they cost least; appended buckets in two tiers (LadderCalendar)
// where it does not, where unlinking and linking list nodes at random places
// missed memory three to five times an event; only the second lets the
// engine look ahead along the queue (docs/benchmarks.md).

#include "exact/event.hpp"
#include "exact/ladder_calendar.hpp"
#include "exact/linked_calendar.hpp"

#include <cstdint>

namespace particlesim {

class EventCalendar {
public:
    using LookAhead = LadderCalendar::LookAhead;

    // Every owner starts with `initial`; replace() sets each. `large`: the
    // two tiers, for a state that outgrows the caches.
    EventCalendar(std::uint32_t owners, const Event& initial, bool large)
        : large_(large), linked_(large ? 0 : owners, initial), ladder_(large ? owners : 0, initial) {}

    [[nodiscard]] bool empty() const { return large_ ? ladder_.empty() : linked_.empty(); }
    [[nodiscard]] std::uint32_t earliest_owner() {
        return large_ ? ladder_.earliest_owner() : linked_.earliest_owner();
    }
    [[nodiscard]] const Event& earliest() { return large_ ? ladder_.earliest() : linked_.earliest(); }
    [[nodiscard]] const Event& entry(std::uint32_t owner) const {
        return large_ ? ladder_.entry(owner) : linked_.entry(owner);
    }
    void replace(std::uint32_t owner, const Event& event) {
        if (large_) {
            ladder_.replace(owner, event);
        } else {
            linked_.replace(owner, event);
        }
    }

    // The look ahead (LadderCalendar::for_each_coming()); nothing to visit
    // in the linked buckets.
    template <typename Visit>
    void for_each_coming(LookAhead& look, Visit&& visit) const {
        if (large_) ladder_.for_each_coming(look, visit);
    }
    void prefetch_entry(std::uint32_t owner) const {
        if (large_) ladder_.prefetch_entry(owner);
    }

private:
    bool large_;
    LinkedCalendar linked_;  // empty when large_
    LadderCalendar ladder_;  // empty unless large_
};

}  // namespace particlesim
