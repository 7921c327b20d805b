#pragma once
// The world every engine simulates (rules.md "World"): a square box [0, L]^2
// and N disks of one radius r. Steps and output mode are not part of it: they
// belong to a scene file and to the program that runs it (scene.hpp).

namespace particlesim {

struct World {
    double box_size = 0.0;  // L
    double radius = 0.0;    // r

    // Every centre lies in [lower(), upper()] on both axes.
    [[nodiscard]] double lower() const { return radius; }
    [[nodiscard]] double upper() const { return box_size - radius; }
};

}  // namespace particlesim
