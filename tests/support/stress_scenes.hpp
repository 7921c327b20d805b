#pragma once
// Adversarial scenes for the stability tests (quick ones in CTest, long ones
// in the benchmark tree), and the check every step of them must pass.

#include "core/random.hpp"
#include "disk.hpp"
#include "named_scene.hpp"
#include "particlesim/accuracy.hpp"
#include "particlesim/random_scene.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace stress_scenes {

using namespace particlesim;
using test_scenes::disk;

inline std::vector<NamedScene> all() {
    std::vector<NamedScene> scenes;
    SplitMix64 rng(77);
    {
        // Pairs whose closest approach is 2r within a few ulps, either side.
        NamedScene s{"near-grazing pairs", {1000.0, 1.0}, 200, {}};
        for (int k = 0; k < 40; ++k) {
            const double y = 20.0 + 24.0 * k;
            const double offset = 2.0 + (k - 20) * 1e-15;
            s.particles.push_back(disk(100.0, y, 1.0, 0.0));
            s.particles.push_back(disk(300.0, y + offset, -1.0, 0.0));
        }
        scenes.push_back(std::move(s));
    }
    {
        // Centres a hair apart, approaching or receding: they overlap.
        NamedScene s{"near-coincident centres", {100.0, 1.0}, 200, {}, true};
        for (int k = 0; k < 20; ++k) {
            const double x = 10.0 + 4.0 * k;
            s.particles.push_back(disk(x, 50.0, 0.3, -0.2));
            s.particles.push_back(disk(x + 1e-12 * (k + 1), 50.0 + 1e-13, -0.3 * (k % 3), 0.25));
        }
        scenes.push_back(std::move(s));
    }
    {
        // A touching line moving together (the original design's worst case),
        // into a wall and back through itself.
        NamedScene s{"line moving together", {200.0, 1.0}, 400, {}};
        for (int k = 0; k < 60; ++k) s.particles.push_back(disk(30.0 + 2.0 * k, 100.0, 1.5, 0.0));
        scenes.push_back(std::move(s));
    }
    {
        // Everything on one wall, pressing into it, touching neighbours.
        NamedScene s{"everything against one wall", {400.0, 1.0}, 300, {}};
        for (int k = 0; k < 150; ++k)
            s.particles.push_back(disk(1.0, 2.0 + 2.0 * k, -0.5 - rng.uniform(), rng.uniform() - 0.5));
        scenes.push_back(std::move(s));
    }
    {
        // A lattice of head-on pairs, all touching at t = 0.5 of step 1 on the
        // same instant, plus a ring converging on one point.
        NamedScene s{"simultaneous collisions", {200.0, 1.0}, 100, {}};
        for (int row = 0; row < 10; ++row) {
            for (int column = 0; column < 8; ++column) {
                const double x = 10.0 + 12.0 * column;
                const double y = 10.0 + 8.0 * row;
                s.particles.push_back(disk(x, y, 1.0, 0.0));
                s.particles.push_back(disk(x + 3.0, y, -1.0, 0.0));
            }
        }
        for (int k = 0; k < 12; ++k) {
            const double angle = 2.0 * 3.14159265358979 * k / 12.0;
            s.particles.push_back(disk(150.0 + 20.0 * std::cos(angle), 150.0 + 20.0 * std::sin(angle),
                                       -2.0 * std::cos(angle), -2.0 * std::sin(angle)));
        }
        scenes.push_back(std::move(s));
    }
    {
        NamedScene s{"huge box (L = 1e12, r = 1e-3)", {1e12, 1e-3}, 100, {}};
        s.particles = make_random_particles(300, s.world, {3, {}});
        scenes.push_back(std::move(s));
    }
    {
        // The rules' speeds for r = 1e-9, L = 1 reach 1.25e8 boxes a step.
        NamedScene s{"tiny radius (r = 1e-9, L = 1)", {1.0, 1e-9}, 100, {}};
        s.particles = make_random_particles(300, s.world, {4, {}});
        scenes.push_back(std::move(s));
    }
    {
        NamedScene s{"zero velocities", {50.0, 1.0}, 50, {}};
        s.particles = make_random_particles(100, s.world, {5, SpeedRange{0.0, 0.0}});
        scenes.push_back(std::move(s));
    }
    {
        NamedScene s{"speeds far above L per step", {100.0, 1.0}, 100, {}};
        s.particles = make_random_particles(200, s.world, {6, SpeedRange{1e6, 1e9}});
        scenes.push_back(std::move(s));
    }
    return scenes;
}

// The state a step must leave: finite, every centre in [r, L - r] exactly.
inline bool valid_state(std::span<const Particle> particles, const World& params) {
    for (const Particle& p : particles) {
        if (!p.position.allFinite() || !p.velocity.allFinite()) return false;
        if (p.position.minCoeff() < params.lower() || p.position.maxCoeff() > params.upper()) return false;
    }
    return true;
}

// Runs `steps` steps, checking every one; returns the largest relative energy
// drift seen, or infinity at the first invalid state.
template <typename Engine>
double run_checked(Engine& engine, const World& params, std::int64_t steps) {
    const double initial = total_kinetic_energy(engine.particles());
    double largest = 0.0;
    for (std::int64_t s = 0; s < steps; ++s) {
        engine.step();
        if (!valid_state(engine.particles(), params)) return INFINITY;
        largest = std::max(largest, std::abs(relative_energy_drift(initial, total_kinetic_energy(engine.particles()))));
    }
    return largest;
}

// The crowded box of the long stability run (area fraction 0.39).
inline NamedScene crowded_box() {
    NamedScene s{"crowded box", {40.0, 1.0}, 0, {}};
    s.particles = make_random_particles(200, s.world, {8, SpeedRange{0.1, 1.0}});
    return s;
}

}  // namespace stress_scenes
