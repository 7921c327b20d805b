#include "input/scene_checks.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace particlesim {

std::size_t max_particle_count() {
    // Everything a run keeps per particle (state, step and grid buffers) stays
    // well below this (docs/benchmarks.md gives the peak).
    constexpr std::size_t bytes_per_particle = 256;
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGE_SIZE);
    const std::size_t by_memory = pages > 0 && page_size > 0 ? static_cast<std::size_t>(pages) / bytes_per_particle *
                                                                   static_cast<std::size_t>(page_size)
                                                             : std::size_t{1} << 24;
    return std::min<std::size_t>(by_memory, 0xfffffffeU);
}

void require_valid_scene(const char* engine, const World& world, std::span<const Particle> particles,
                         CentresIn centres) {
    const auto fail = [engine](const std::string& what) {
        throw std::invalid_argument(std::string(engine) + ": " + what);
    };
    const auto in_range = [](double length) { return length >= min_length && length <= max_magnitude; };
    if (!in_range(world.box_size)) fail("box size must lie in [1e-60, 1e60] (the accepted range)");
    if (!in_range(world.radius)) fail("radius must lie in [1e-60, 1e60] (the accepted range)");
    if (!(2.0 * world.radius <= world.box_size)) fail("2 * radius must be <= box size");
    if (particles.size() >= std::size_t{0xffffffffU}) fail("too many particles");
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        if (std::isnan(p.position.x()) || std::isnan(p.position.y()))
            fail("particle " + std::to_string(i) + " has a position that is not a number (NaN)");
        if (std::isnan(p.velocity.x()) || std::isnan(p.velocity.y()))
            fail("particle " + std::to_string(i) + " has a velocity that is not a number (NaN)");
        if (centres == CentresIn::walled_box) {
            const bool inside = p.position.x() >= world.lower() && p.position.x() <= world.upper() &&
                                p.position.y() >= world.lower() && p.position.y() <= world.upper();
            if (!inside) fail("particle " + std::to_string(i) + " is outside [r, L - r]");
        } else {
            const double slack = centres == CentresIn::periodic_saved ? world.box_size : 0.0;
            const auto in_box = [&](double c) { return c >= -slack && c < world.box_size + slack; };
            if (!(in_box(p.position.x()) && in_box(p.position.y())))
                fail("particle " + std::to_string(i) + " is outside [0, L) (a periodic box)");
        }
        if (!(std::fabs(p.velocity.x()) <= max_magnitude && std::fabs(p.velocity.y()) <= max_magnitude))
            fail("particle " + std::to_string(i) + " has a velocity component beyond 1e60 (the accepted range)");
    }
}

}  // namespace particlesim
