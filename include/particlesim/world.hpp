#pragma once
// The world every engine simulates (rules.md "World"): a square box [0, L]^2
// and N disks of one radius r. Steps and output mode are not part of it: they
// belong to a scene file and to the program that runs it (scene.hpp).

#include <cstdint>
#include <optional>
#include <string_view>

namespace particlesim {

// The accepted range: L and r in [min_length, max_magnitude], every position
// and velocity component at most max_magnitude in magnitude. Inside it no
// formula of either engine overflows or underflows harmfully, so a scene and
// the same scene scaled by 2^k give the same collisions and exactly the
// scaled states (docs/accepted-range.md works it out). Readers refuse, and
// engines throw std::invalid_argument for, anything outside it.
inline constexpr double min_length = 1e-60;
inline constexpr double max_magnitude = 1e60;

// The box's edges: walls (rules.md), or periodic: the square wraps, a disk
// meets the nearest image of another, and positions lie in [0, L) (the exact
// engine only).
enum class Boundary : std::uint8_t { walls, periodic };

// "walls" or "periodic", as the programs' --boundary names them; empty for any other name.
inline std::optional<Boundary> boundary_named(std::string_view name) {
    if (name == "walls") return Boundary::walls;
    if (name == "periodic") return Boundary::periodic;
    return std::nullopt;
}

struct World {
    double box_size = 0.0;  // L
    double radius = 0.0;    // r

    // Every centre lies in [lower(), upper()] on both axes.
    [[nodiscard]] double lower() const { return radius; }
    [[nodiscard]] double upper() const { return box_size - radius; }
};

}  // namespace particlesim
