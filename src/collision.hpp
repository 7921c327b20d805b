#pragma once
// A candidate or accepted collision, and the one total order that encodes
// every tie rule (event_order.hpp).

#include "event_order.hpp"

#include <cstdint>
#include <tuple>

namespace particlesim {

enum class CollisionKind : std::uint8_t { wall = 0, pair = 1 };

struct Collision {
    double time = 0.0;  // within the step (or micro-step), from its start
    CollisionKind kind = CollisionKind::wall;
    // Stored indices: i the particle (wall) or the lower index (pair), j the
    // higher one (0 for a wall). While a Simulation stores its particles out
    // of the user's order (storage_order.hpp), a pair's may come either way.
    std::uint32_t i = 0;
    std::uint32_t j = 0;

    static Collision wall(double time, std::uint32_t particle) { return {time, CollisionKind::wall, particle, 0}; }
    static Collision pair(double time, std::uint32_t lower, std::uint32_t higher) {
        return {time, CollisionKind::pair, lower, higher};
    }

    friend bool operator<(const Collision& a, const Collision& b) { return comes_before(a, b); }
    friend bool operator==(const Collision& a, const Collision& b) {
        return std::tie(a.time, a.kind, a.i, a.j) == std::tie(b.time, b.kind, b.i, b.j);
    }
};

}  // namespace particlesim
