#pragma once
// An event of the exact engine: what happens, to whom, when. Its order is
// the rules' total order (t, kind, i, j) (core/event_order.hpp).

#include "core/event_order.hpp"

#include <cstdint>

namespace particlesim {

enum class EventKind : std::uint8_t {
    wall = 0,  // the same kinds and order as Collision: walls first
    pair = 1,
    cell_crossing = 2,  // bookkeeping only, changes no motion
};

struct Event {
    double time = 0.0;  // absolute, in steps since the start
    EventKind kind = EventKind::wall;
    std::uint32_t i = 0;  // the particle, or the lower index of a pair
    std::uint32_t j = 0;  // pair: the higher index; crossing: the cell entered

    friend bool operator<(const Event& a, const Event& b) { return comes_before(a, b); }
};

}  // namespace particlesim
