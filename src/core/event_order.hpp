#pragma once
// The one total order of rules.md "Order", (time, kind, i, j), for anything
// with those four members: the stepped engine's candidates and the exact
// engine's events. It encodes every tie rule (walls before pairs, then the
// lowest indices), so both engines break ties the same way.

#include <tuple>

namespace particlesim {

template <typename Event>
bool comes_before(const Event& a, const Event& b) {
    // Times almost always differ: decided by one comparison.
    if (a.time != b.time) return a.time < b.time;
    return std::tie(a.kind, a.i, a.j) < std::tie(b.kind, b.i, b.j);
}

}  // namespace particlesim
