#pragma once
// A candidate or accepted collision, and the one total order that encodes
// every tie rule (event_order.hpp).

#include "core/event_order.hpp"

#include <cstdint>
#include <tuple>

namespace particlesim {

enum class CollisionKind : std::uint8_t { wall = 0, pair = 1 };

// What the selection leaves for each particle in place of a partner's
// stored index.
inline constexpr std::uint32_t no_collision = 0xffffffffU;
inline constexpr std::uint32_t wall_collision = 0xfffffffeU;

struct Collision {
    double time = 0.0;  // within the step (or micro-step), from its start
    CollisionKind kind = CollisionKind::wall;
    // Stored indices: i the particle (wall) or the lower index (pair), j the
    // higher one (0 for a wall). While the stepped engine stores its particles
    // out of the user's order (stepped/storage_order.hpp), a pair's may come
    // either way. There is deliberately no operator<: stored indices are not
    // the rules' order; compare with CandidateOrder (stepped/step_pipeline.hpp),
    // which maps them to the user's indices.
    std::uint32_t i = 0;
    std::uint32_t j = 0;

    static Collision wall(double time, std::uint32_t particle) { return {time, CollisionKind::wall, particle, 0}; }
    static Collision pair(double time, std::uint32_t lower, std::uint32_t higher) {
        return {time, CollisionKind::pair, lower, higher};
    }

    friend bool operator==(const Collision& a, const Collision& b) {
        return std::tie(a.time, a.kind, a.i, a.j) == std::tie(b.time, b.kind, b.i, b.j);
    }
};

}  // namespace particlesim
