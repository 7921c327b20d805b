#pragma once
// The run loop both engines share: step, then show the observer the state
// at that whole step. An engine derives from WholeStepRunner<Engine> and
// provides step(), steps_done() and particles().

#include "particlesim/particle.hpp"

#include <concepts>
#include <cstdint>
#include <span>

namespace particlesim {

template <typename Engine>
class WholeStepRunner {
public:
    // Runs `steps` steps; after each, calls observe(step number, particles).
    template <typename Observer>
        requires std::invocable<Observer&, std::int64_t, std::span<const Particle>>
    void run(std::int64_t steps, Observer&& observe) {
        Engine& engine = static_cast<Engine&>(*this);
        for (std::int64_t s = 0; s < steps; ++s) {
            engine.step();
            observe(engine.steps_done(), engine.particles());
        }
    }
    // Without an observer, the particles are not asked for between steps
    // (the Simulation would restore their user order each time).
    void run(std::int64_t steps) {
        Engine& engine = static_cast<Engine&>(*this);
        for (std::int64_t s = 0; s < steps; ++s) engine.step();
    }
};

}  // namespace particlesim
