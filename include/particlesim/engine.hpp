#pragma once
// What an engine offers, stated once as a C++20 concept that both engines
// (SteppedSimulation, ExactSimulation) satisfy, and the one run loop written
// against it: step, then show the observer the state at that whole step.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <concepts>
#include <cstdint>
#include <span>

namespace particlesim {

// The largest grid an engine's options may impose (G x G cells), so that the
// cell arrays stay a modest size.
inline constexpr int max_grid_cells = 4096;

// What one step (or a whole run, summed) did, in either engine.
struct StepCounts {
    std::uint64_t particle_collisions = 0;
    std::uint64_t wall_collisions = 0;
    std::uint64_t pair_tests = 0;  // contact-time evaluations: the cost of finding the collisions

    StepCounts& operator+=(const StepCounts& other) {
        particle_collisions += other.particle_collisions;
        wall_collisions += other.wall_collisions;
        pair_tests += other.pair_tests;
        return *this;
    }
};

template <typename E>
concept Engine = requires(E& engine, const E& observed) {
    engine.step();                                                               // one whole step
    { observed.particles() } -> std::convertible_to<std::span<const Particle>>;  // in the user's order
    { observed.world() } -> std::convertible_to<const World&>;
    { observed.steps_done() } -> std::convertible_to<std::int64_t>;
    { observed.last_step() } -> std::convertible_to<const StepCounts&>;
    { observed.totals() } -> std::convertible_to<const StepCounts&>;
};

// Runs `steps` steps; after each, calls observe(step number, particles).
template <Engine E, typename Observer>
requires std::invocable<Observer&, std::int64_t, std::span<const Particle>>
void run(E& engine, std::int64_t steps, Observer&& observe) {
    for (std::int64_t s = 0; s < steps; ++s) {
        engine.step();
        observe(engine.steps_done(), engine.particles());
    }
}

// Without an observer the particles are not asked for between steps, which
// saves a large stepped scene from restoring the user's order every step.
template <Engine E>
void run(E& engine, std::int64_t steps) {
    for (std::int64_t s = 0; s < steps; ++s) engine.step();
}

}  // namespace particlesim
