#pragma once
// The derived constants that every physics function needs, computed once per
// world so that every engine rounds them the same way.

#include "particlesim/world.hpp"

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

}  // namespace particlesim
