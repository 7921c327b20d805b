#pragma once
// The derived constants that every physics function needs, computed once per
// scene so that every engine rounds them the same way.

#include "particlesim/sim_params.hpp"

namespace particlesim {

struct Box {
    double lower = 0.0;           // r: lowest coordinate of a centre
    double upper = 0.0;           // L - r: highest coordinate of a centre
    double contact_dist_sq = 0.0;  // (2r)^2: squared centre distance at contact

    static Box of(const SimParams& params) {
        const double diameter = 2.0 * params.radius;
        return {params.lower(), params.upper(), diameter * diameter};
    }
};

}  // namespace particlesim
