#pragma once
// The scalar parameters of a scene: the box, the radius, the number of steps
// and the output mode (rules.md "World", io.md "Input scene").

#include <cstdint>

namespace particlesim {

enum class OutputMode { print, perf };

struct SimParams {
    double box_size = 0.0;   // L: the box is [0, L] x [0, L]
    double radius = 0.0;     // r: every disk has this radius
    std::int64_t steps = 0;  // S
    OutputMode mode = OutputMode::perf;

    // Every centre lies in [lower(), upper()] on both axes.
    [[nodiscard]] double lower() const { return radius; }
    [[nodiscard]] double upper() const { return box_size - radius; }
};

}  // namespace particlesim
