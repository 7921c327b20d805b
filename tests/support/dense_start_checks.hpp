#pragma once
// What every dense start (simgen crystal, compressed) promises: the area
// fraction asked for, no two disks closer than 2r (by the nearest image in
// a periodic box), every centre inside (r from the walls, or in [0, L)),
// zero total momentum, and a kinetic energy of exactly (N - 1) kT; and the
// exact engine runs it.

#include "check.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/world.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dense_start {

inline void check_start(const particlesim::Scene& scene, double fraction, double kT,
                        particlesim::Boundary boundary = particlesim::Boundary::walls) {
    const bool periodic = boundary == particlesim::Boundary::periodic;
    const double r = scene.world.radius, side = scene.world.box_size;
    const std::size_t n = scene.particles.size();
    CHECK_NEAR(static_cast<double>(n) * std::numbers::pi * r * r / (side * side), fraction, 1e-12 * fraction);
    const auto image = [&](double d) { return periodic ? d - side * std::round(d / side) : d; };
    double closest_sq = INFINITY, kinetic = 0.0;
    particlesim::Vec2 momentum(0.0, 0.0);
    bool inside = true;
    for (std::size_t i = 0; i < n; ++i) {
        const particlesim::Particle& p = scene.particles[i];
        for (int axis = 0; axis < 2; ++axis) {
            const double x = p.position[axis];
            inside = inside && (periodic ? x >= 0.0 && x < side : x >= r && x <= side - r);
        }
        for (std::size_t j = i + 1; j < n; ++j) {
            const particlesim::Vec2 d = scene.particles[j].position - p.position;
            closest_sq = std::min(closest_sq, image(d.x()) * image(d.x()) + image(d.y()) * image(d.y()));
        }
        momentum += p.velocity;
        kinetic += 0.5 * p.velocity.squaredNorm();
    }
    CHECK(inside);
    CHECK(n < 2 || closest_sq > 4.0 * r * r);
    CHECK(momentum.norm() <= 1e-12 * std::sqrt(static_cast<double>(n) * kT + 1.0) * static_cast<double>(n));
    CHECK_NEAR(kinetic, static_cast<double>(n > 0 ? n - 1 : 0) * kT, 1e-12 * (kinetic + 1.0));
}

// The exact engine accepts the start (no overlap) and runs it for `steps`
// steps, with more than `collisions` pair collisions, conserving the energy.
inline void check_exact_run(const particlesim::Scene& scene, particlesim::Boundary boundary, int steps,
                            std::uint64_t collisions) {
    particlesim::ExactOptions options;
    options.boundary = boundary;
    particlesim::ExactSimulation engine(scene.world, scene.particles, options);
    double before = 0.0, after = 0.0;
    for (const particlesim::Particle& p : engine.particles()) before += p.velocity.squaredNorm();
    for (int s = 0; s < steps; ++s) engine.step();
    for (const particlesim::Particle& p : engine.particles()) after += p.velocity.squaredNorm();
    CHECK(engine.totals().particle_collisions > collisions);
    CHECK_NEAR(after, before, 1e-9 * before);
}

}  // namespace dense_start
