#pragma once
// The stepped engine: the step rules of rules.md, one whole step at a time
// (detect, order, select, resolve, advance), exact to the bit whatever the
// pair search and the number of threads.

#include "particlesim/engine.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <vector>

namespace particlesim {

// How the engine finds the pairs that may collide in a step. Every choice
// gives the same candidates, so the same output.
enum class PairSearch {
    automatic,    // the cheapest for the scene: brute force (tiny), paths (sparse) or grid
    brute_force,  // every pair: the reference
    grid,         // uniform grid over the swept paths, exact for any speed
    // Each particle's path kept between its collisions: sparse scenes. Where
    // the paths crowd together (disks piled up, a row moving along itself)
    // it hands over to the grid for the rest of the run, which finds the
    // same candidates, rather than watch nearly every pair.
    paths,
};

// Its name on simcli's command line and in reports: auto, brute, grid, paths.
[[nodiscard]] const char* pair_search_name(PairSearch search);

// The most worker threads an engine takes (SteppedOptions::threads): each
// keeps buffers of its own, and more threads than this would hold memory
// and time for nothing on any machine built today.
inline constexpr int max_threads = 1024;

// Every option is checked when the engine is built; a bad one throws
// std::invalid_argument naming it. None changes the results, except substeps.
struct SteppedOptions {
    PairSearch pair_search = PairSearch::automatic;
    // Imposes a G x G grid, 1 <= G <= max_grid_cells; only with PairSearch::grid.
    // Empty: the grid is sized from each step's motion.
    std::optional<int> grid_cells = std::nullopt;
    // Worker threads, 1 to max_threads. Empty: OpenMP's default; a scene of up to 20000
    // particles then runs its steps on one thread in the stretches where
    // short trials find that faster (a shared or busy machine), and a larger
    // scene runs such trials when its threads wait for a CPU (another process
    // taking turns on their cores; Linux only). The results are the same for
    // every thread count.
    std::optional<int> threads = std::nullopt;
    // Micro-steps of length 1 / substeps per step (rules.md "Substeps"), >= 1.
    int substeps = 1;
    // Steps between sorts of the stored particles by position, >= 0 (0: never).
    // Empty: every 8 steps from 65536 particles on, and from 8192 where two
    // or more threads share the grid search. Only speed depends on it.
    std::optional<int> sort_by_position_every = std::nullopt;
};

class SteppedSimulation {
public:
    // Throws std::invalid_argument for a world or particles that break
    // rules.md "World", and for a bad option.
    SteppedSimulation(const World& world, std::vector<Particle> particles, const SteppedOptions& options = {});
    ~SteppedSimulation();
    // Movable; a moved-from SteppedSimulation may only be assigned to or destroyed.
    SteppedSimulation(SteppedSimulation&&) noexcept;
    SteppedSimulation& operator=(SteppedSimulation&&) noexcept;

    // Continues a run saved by save() bit for bit (with the same substeps;
    // searches and threads may differ: they never change a result). Throws
    // std::invalid_argument for a saved state that does not fit `world` or is damaged.
    static SteppedSimulation restore(const World& world, std::istream& saved, const SteppedOptions& options = {});
    // Writes the state after the last whole step (particles, steps done,
    // totals) as text, exactly: the step rules need nothing else to go on.
    void save(std::ostream& out) const;

    // One whole step: `substeps` micro-steps under the step rules.
    void step();

    // In the user's order. A large scene stored in position order is put back
    // in the user's order on demand, so not to be called from two threads at once.
    [[nodiscard]] std::span<const Particle> particles() const;
    [[nodiscard]] const World& world() const;
    [[nodiscard]] std::int64_t steps_done() const;
    // Summed over the micro-steps of the last step.
    [[nodiscard]] const StepCounts& last_step() const;
    [[nodiscard]] const StepCounts& totals() const;
    // The pair search in use: the one asked for, or the one automatic chose;
    // the grid once the paths search has handed over to it.
    [[nodiscard]] PairSearch pair_search() const;
    // The most threads a step uses: the ones asked for, or OpenMP's default.
    [[nodiscard]] int threads() const;
    // Of the steps this object ran, those that the thread choice (threads not
    // set: SteppedOptions::threads) ran on one thread.
    [[nodiscard]] std::int64_t steps_on_one_thread() const;

private:
    class Implementation;
    std::unique_ptr<Implementation> engine_;
};

}  // namespace particlesim
