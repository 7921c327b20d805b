#pragma once
// A scene in motion: owns the particles and every buffer the step pipeline
// reuses, steps under the rules, and reports each step to an observer.

#include "particlesim/box.hpp"
#include "particlesim/collision.hpp"
#include "particlesim/pair_search.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/sim_params.hpp"
#include "particlesim/step_counts.hpp"
#include "particlesim/storage_order.hpp"
#include "particlesim/whole_step_runner.hpp"

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
    int substeps = 1;    // micro-steps of length 1/substeps per step (rules.md "Substeps")
    // Steps between sorts of the stored particles by position (see
    // storage_order.hpp): 0 never; automatic: every 8 steps from 65536
    // particles on. Results do not depend on it, only speed does.
    int sort_by_position_every = automatic_sorting;
    static constexpr int automatic_sorting = -1;
};

class Simulation : public WholeStepRunner<Simulation> {
public:
    // Throws std::invalid_argument for a scene that breaks rules.md "World".
    Simulation(const SimParams& params, std::vector<Particle> particles, const SimOptions& options = {});
    ~Simulation();
    Simulation(Simulation&&) noexcept;
    Simulation& operator=(Simulation&&) noexcept;

    // One whole step: `substeps` micro-steps under the step rules.
    void step();

    // In the user's order: a large scene's storage order is undone on demand
    // (so, unlike most const functions, not to be called from two threads at once).
    [[nodiscard]] std::span<const Particle> particles() const;
    [[nodiscard]] const SimParams& params() const { return params_; }
    [[nodiscard]] std::int64_t steps_done() const { return steps_done_; }
    [[nodiscard]] int threads() const { return threads_; }
    // Summed over the micro-steps of the last step.
    [[nodiscard]] const StepCounts& last_step() const { return last_step_; }
    [[nodiscard]] const StepCounts& totals() const { return totals_; }
    // The search the last step used (automatic resolves to brute or grid).
    [[nodiscard]] Broadphase last_broadphase() const { return last_broadphase_; }

private:
    void micro_step(double duration);
    void find_pair_candidates(const PairSearchInput& input);

    SimParams params_;
    Box box_;
    SimOptions options_;
    int threads_ = 1;
    // Mutable: particles() restores the user's order, which changes no state.
    mutable std::vector<Particle> particles_;
    mutable StorageOrder storage_order_;
    int sort_every_ = 0;  // steps; 0: never

    // Step buffers, sized once and reused so that a step allocates nothing.
    std::vector<double> wall_time_;
    std::vector<std::uint32_t> collision_of_;  // by particle: its number in accepted_ (from 1), 0 if none
    std::vector<Collision> candidates_;
    std::vector<Collision> merge_scratch_;  // the walls, while a busy step's lists are merged
    std::vector<Collision> accepted_;
    std::vector<ThreadCandidates> thread_candidates_;
    std::unique_ptr<GridSearch> grid_;

    std::int64_t steps_done_ = 0;
    StepCounts last_step_;
    StepCounts totals_;
    Broadphase last_broadphase_ = Broadphase::brute;
};

}  // namespace particlesim
