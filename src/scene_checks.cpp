#include "scene_checks.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace particlesim {

void require_valid_scene(const char* engine, const World& world, std::span<const Particle> particles) {
    const auto fail = [engine](const std::string& what) {
        throw std::invalid_argument(std::string(engine) + ": " + what);
    };
    if (!(std::isfinite(world.box_size) && world.box_size > 0.0)) fail("box size must be finite and > 0");
    if (!(std::isfinite(world.radius) && world.radius > 0.0)) fail("radius must be finite and > 0");
    if (!(2.0 * world.radius <= world.box_size)) fail("2 * radius must be <= box size");
    if (particles.size() >= std::size_t{0xffffffffU}) fail("too many particles");
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Particle& p = particles[i];
        const bool inside = p.position.x() >= world.lower() && p.position.x() <= world.upper() &&
                            p.position.y() >= world.lower() && p.position.y() <= world.upper();
        if (!inside) fail("particle " + std::to_string(i) + " is outside [r, L - r]");
        if (!p.velocity.allFinite()) fail("particle " + std::to_string(i) + " has a non-finite velocity");
    }
}

}  // namespace particlesim
