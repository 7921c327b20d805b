#pragma once
// The one total order of rules.md "Order", (time, kind, i, j), for anything
// with those four members: the stepped engine's candidates and the exact
// engine's events. It encodes every tie rule (walls before pairs, then the
// lowest indices), so both engines break ties the same way.

#include <tuple>

namespace particlesim {

template <typename Event>
bool comes_before(const Event& a, const Event& b) {
    return std::tie(a.time, a.kind, a.i, a.j) < std::tie(b.time, b.kind, b.i, b.j);
}

}  // namespace particlesim
