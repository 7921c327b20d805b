#pragma once
// The derived constants that every physics function needs, computed once per
// world so that every engine rounds them the same way.

#include "particlesim/world.hpp"

#include <cmath>

namespace particlesim {

struct Box {
    double side = 0.0;             // L
    double lower = 0.0;            // r: lowest coordinate of a centre
    double upper = 0.0;            // L - r: highest coordinate of a centre
    double contact_dist_sq = 0.0;  // (2r)^2: squared centre distance at contact

    static Box of(const World& world) {
        const double diameter = 2.0 * world.radius;
        return {world.box_size, world.lower(), world.upper(), diameter * diameter};
    }
};

// The distance a pair must be kept within, for a contact distance of 2r:
// above 2r by far more than the rounding of a double-precision pair test
// (a few ulps of L in dp) and of free motion along a line over 1024 steps
// (at most 2^-51 L a step and coordinate while a particle stays in the box).
// The searches' reach, and the exact engine's smallest cell.
inline double contact_reach(const Box& box) {
    return std::sqrt(box.contact_dist_sq) * (1.0 + 0x1p-30) + 0x1p-36 * box.side;
}

// Whether a periodic box of this world holds `cells` cells a side, each at
// least a contact reach wide (uniform_grid.hpp's periodic_cells_at_least).
inline bool holds_contact_cells(const World& world, int cells) {
    return !(world.box_size / cells < contact_reach(Box::of(world)));
}

}  // namespace particlesim
