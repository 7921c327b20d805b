#pragma once
// Random test scenes across the regimes that matter: sparse and dense boxes,
// slow particles and particles faster than the box per step, overlapping starts.

#include "core/random.hpp"
#include "named_scene.hpp"
#include "particlesim/random_scene.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace random_scenes {

// Scene number `k` of a reproducible family; k varies the regime.
inline NamedScene make(std::uint64_t k) {
    using namespace particlesim;
    SplitMix64 rng(1000 + k);
    NamedScene scene;
    const int regime = static_cast<int>(k % 5);
    const std::size_t count = 2 + rng.next() % (regime == 4 ? 40 : 300);
    const double box_size = regime == 1 ? 60.0 + 100.0 * rng.uniform() : 200.0 + 20000.0 * rng.uniform();
    scene.world = World{box_size, 1.0};
    scene.steps = 30;
    const double speed_scale = regime == 2 ? 3.0 * box_size : (regime == 3 ? 0.05 : box_size / 4.0);

    if (regime == 0 || regime == 3) {
        // Non-overlapping random scene with the rules' generator.
        const double max_speed = regime == 3 ? speed_scale : box_size / 4.0;
        const std::size_t fits =
            std::min<std::size_t>(count, static_cast<std::size_t>(0.3 * box_size * box_size / 3.2));
        scene.particles =
            make_random_particles(std::max<std::size_t>(fits, 2), scene.world, {k, SpeedRange{0.0, max_speed}});
        return scene;
    }
    // Positions anywhere (overlaps allowed), velocities of the regime's scale;
    // some particles start on a wall, some at rest.
    const double lower = scene.world.lower();
    const double upper = scene.world.upper();
    for (std::size_t i = 0; i < count; ++i) {
        Particle p;
        p.position = Vec2(lower + rng.uniform() * (upper - lower), lower + rng.uniform() * (upper - lower));
        if (rng.next() % 8 == 0) p.position.x() = rng.next() % 2 ? lower : upper;
        p.velocity = Vec2((2 * rng.uniform() - 1) * speed_scale, (2 * rng.uniform() - 1) * speed_scale);
        if (rng.next() % 10 == 0) p.velocity = Vec2::Zero();
        scene.particles.push_back(p);
    }
    return scene;
}

// Scene number `k` of a family where a cluster of particles shares a few
// grid cells, fast enough to be binned over many time slices: small
// clusters overflow a few cells, large ones crowd them.
inline NamedScene make_clustered(std::uint64_t k) {
    using namespace particlesim;
    SplitMix64 rng(5000 + k);
    NamedScene scene;
    const double box_size = 20000.0;
    scene.world = World{box_size, 1.0};
    scene.steps = 20;
    const std::size_t spread = 100 + rng.next() % 400;
    const std::size_t clustered = k % 2 == 0 ? 20 + rng.next() % 60 : 300 + rng.next() % 300;
    const double patch = 5.0 + 200.0 * rng.uniform();
    const double corner = 1.0 + rng.uniform() * (box_size - patch - 2.0);
    for (std::size_t i = 0; i < spread + clustered; ++i) {
        Particle p;
        const double extent = i < spread ? box_size - 2.0 : patch;
        const double origin = i < spread ? 1.0 : corner;
        p.position = Vec2(origin + rng.uniform() * extent, origin + rng.uniform() * extent);
        const double speed = box_size / 8.0 * (1.0 + rng.uniform());
        const double angle = 6.283185307179586 * rng.uniform();
        p.velocity = Vec2(speed * std::cos(angle), speed * std::sin(angle));
        scene.particles.push_back(p);
    }
    return scene;
}

}  // namespace random_scenes
