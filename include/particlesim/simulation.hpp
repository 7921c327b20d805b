#pragma once
// A scene in motion: owns the particles and every buffer the step pipeline
// reuses, steps under the rules, and reports each step to an observer.

#include "particlesim/box.hpp"
#include "particlesim/collision.hpp"
#include "particlesim/pair_search.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/sim_params.hpp"

#include <concepts>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace particlesim {

class GridSearch;

enum class Broadphase {
    automatic,  // brute force where it is cheaper (tiny scenes), else the grid
    brute,      // every pair: the reference
    grid,       // uniform grid over the swept paths, exact for any speed
};

struct SimOptions {
    Broadphase broadphase = Broadphase::automatic;
    int grid_cells = 0;  // > 0 forces a G x G grid (implies the grid search)
    int threads = 0;     // 0: OpenMP's default
};

// What one step (or a whole run, summed) did.
struct StepCounts {
    std::uint64_t pair_tests = 0;  // contact-time evaluations by the pair search
    std::uint64_t candidates = 0;  // distinct wall and pair candidates
    std::uint64_t particle_collisions = 0;
    std::uint64_t wall_collisions = 0;

    StepCounts& operator+=(const StepCounts& other);
};

class Simulation {
public:
    // Throws std::invalid_argument for a scene that breaks rules.md "World".
    Simulation(const SimParams& params, std::vector<Particle> particles, const SimOptions& options = {});
    ~Simulation();
    Simulation(Simulation&&) noexcept;
    Simulation& operator=(Simulation&&) noexcept;

    void step();

    // Runs `steps` steps; after each, calls observe(step number, particles).
    template <typename Observer>
        requires std::invocable<Observer&, std::int64_t, std::span<const Particle>>
    void run(std::int64_t steps, Observer&& observe) {
        for (std::int64_t s = 0; s < steps; ++s) {
            step();
            observe(steps_done_, particles());
        }
    }
    void run(std::int64_t steps) {
        run(steps, [](std::int64_t, std::span<const Particle>) {});
    }

    [[nodiscard]] std::span<const Particle> particles() const { return particles_; }
    [[nodiscard]] const SimParams& params() const { return params_; }
    [[nodiscard]] std::int64_t steps_done() const { return steps_done_; }
    [[nodiscard]] int threads() const { return threads_; }
    [[nodiscard]] const StepCounts& last_step() const { return last_step_; }
    [[nodiscard]] const StepCounts& totals() const { return totals_; }
    // The search the last step used (automatic resolves to brute or grid).
    [[nodiscard]] Broadphase last_broadphase() const { return last_broadphase_; }

private:
    void find_pair_candidates(const PairSearchInput& input);

    SimParams params_;
    Box box_;
    SimOptions options_;
    int threads_ = 1;
    std::vector<Particle> particles_;

    // Step buffers, sized once and reused so that a step allocates nothing.
    std::vector<double> wall_time_;
    std::vector<std::uint8_t> busy_;
    std::vector<Collision> candidates_;
    std::vector<Collision> accepted_;
    std::vector<ThreadCandidates> thread_candidates_;
    std::unique_ptr<GridSearch> grid_;

    std::int64_t steps_done_ = 0;
    StepCounts last_step_;
    StepCounts totals_;
    Broadphase last_broadphase_ = Broadphase::brute;
};

}  // namespace particlesim
