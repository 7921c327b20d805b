#pragma once
// The exact engine (rules.md "Substeps and the exact engine"): continuous-time,
// event-driven hard disks. Every collision happens at its own time, with no
// one-per-step limit; it is the ground truth the stepped engine is measured
// against. It shares the stepped engine's physics and its order of
// simultaneous events (time, kind, i, j), and shows the state at whole steps.

#include "particlesim/engine.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <vector>

namespace particlesim {

// Two disks overlap at the start: real hard disks cannot, so the exact engine
// has no ground truth to offer for the scene.
class OverlappingStart : public std::invalid_argument {
public:
    OverlappingStart(std::uint32_t first, std::uint32_t second);
    [[nodiscard]] std::uint32_t first() const { return first_; }
    [[nodiscard]] std::uint32_t second() const { return second_; }

private:
    std::uint32_t first_;
    std::uint32_t second_;
};

// A step needed far more events than the scene's speeds and density predict:
// typically disks trapped in a gap so narrow that they bounce millions of
// times a step. Thrown by step() instead of running on for hours; the
// simulation cannot continue after it.
class TooManyEvents : public std::runtime_error {
public:
    TooManyEvents(std::int64_t step, std::uint64_t events, double predicted);
    [[nodiscard]] std::int64_t step() const { return step_; }  // 1-based: the step that was running
    [[nodiscard]] std::uint64_t events() const { return events_; }
    [[nodiscard]] double predicted() const { return predicted_; }

private:
    std::int64_t step_;
    std::uint64_t events_;
    double predicted_;
};

// Whole steps the exact engine can count: its clock is a double.
inline constexpr std::int64_t max_exact_steps = std::int64_t{1} << 53;

// The engine's large arrays ask Linux for transparent huge pages, or for
// small ones when the environment holds PARTICLESIM_HUGE_PAGES=0 (read once
// a process). Which is faster depends on the machine (docs/benchmarks.md,
// "Huge pages for the exact engine's arrays"); every result is the same.
struct ExactOptions {
    // Cells per side of the neighbour search, >= 1 (1 tests every pair).
    // Empty: sized from the scene. Every value gives the same events.
    std::optional<int> cells_per_side = std::nullopt;
    // The most events a step may take before step() throws TooManyEvents, >= 1.
    // Empty: 1e6 + 100 x (predicted events per step + N), reached within about a second.
    std::optional<std::uint64_t> max_events_per_step = std::nullopt;
    // Whether each event prefetches what the events a few places behind it
    // in the queue will read, so that their misses to memory overlap, in a
    // queue built for it whose events write to few places (two tiers of
    // appended buckets instead of linked lists): much faster where the state
    // outgrows the caches, slower where it fits (docs/benchmarks.md). Empty:
    // on from 32 768 particles. No effect with one cell. Every value gives
    // the same events.
    std::optional<bool> look_ahead = std::nullopt;
    // Walls, or a periodic box (docs/physics.md): then the particles' centres
    // lie in [0, L) and the box must be at least 5 cells of a contact
    // distance wide (L >= 10 r, a little more); cells_per_side >= 5.
    Boundary boundary = Boundary::walls;
};

class ExactSimulation {
public:
    // Throws std::invalid_argument for a world or particles that break
    // rules.md "World" or a bad option, and OverlappingStart when two disks
    // overlap (touching is allowed: closer than 2r by under 1e-6 of r, or by
    // under 2^-51 L, a few units in the last place of a coordinate).
    ExactSimulation(const World& world, std::vector<Particle> particles, const ExactOptions& options = {});
    ~ExactSimulation();
    // Movable; a moved-from ExactSimulation may only be assigned to or destroyed.
    ExactSimulation(ExactSimulation&&) noexcept;
    ExactSimulation& operator=(ExactSimulation&&) noexcept;

    // Continues a run saved by save() bit for bit; throws std::invalid_argument
    // for a saved state that does not fit `world` or is damaged (among the
    // checks: the disks, moved to the saved step, lie in the cells saved for
    // them and do not overlap).
    static ExactSimulation restore(const World& world, std::istream& saved, const ExactOptions& options = {});
    // Writes the whole state at the last whole step (every particle at its
    // own time stamp, every prediction) as text, exactly.
    void save(std::ostream& out) const;

    // Processes every event up to and including the next whole step. Throws
    // TooManyEvents when the step needs more than max_events_per_step events,
    // and std::overflow_error past max_exact_steps.
    void step();

    // The state at the last whole step; positions clamped into [r, L - r].
    // Made on demand, so not to be called from two threads at once.
    [[nodiscard]] std::span<const Particle> particles() const;
    [[nodiscard]] const World& world() const;
    [[nodiscard]] std::int64_t steps_done() const;
    [[nodiscard]] const StepCounts& last_step() const;
    [[nodiscard]] const StepCounts& totals() const;
    // The pair virial and the walls' impulse summed over every collision
    // since the run started (saved: a restored run goes on from the saved
    // sums, or from 0 for a state saved before they were); their change over
    // an interval gives its pressure (observables.hpp).
    [[nodiscard]] const CollisionSums& collision_sums() const;
    // Particles with more than one collision (wall or particle) in the last
    // step: where the one-collision-per-step rule must differ from this engine.
    [[nodiscard]] std::uint64_t last_step_particles_with_several_events() const;

    // Calendar entries this object has handled: collisions, cell crossings and
    // re-predictions of pair events gone stale. The engine's unit of work
    // (its speed is quoted in events per second); not saved by save().
    [[nodiscard]] std::uint64_t events_processed() const;

    // The neighbour cells in use, per side: the ones asked for, or the ones
    // chosen. 1: each particle's straight line against all the others.
    [[nodiscard]] int cells_per_side() const;

private:
    class Implementation;
    explicit ExactSimulation(std::unique_ptr<Implementation> engine);
    std::unique_ptr<Implementation> engine_;
};

// A rough count of the events (wall and particle collisions) per step of a
// scene, from its speeds and density. Ideal-gas estimate, not a bound: it
// lets a caller refuse runs that would take hours, or never end (a particle
// much faster than the box bounces many times per step).
double estimated_events_per_step(const World& world, std::span<const Particle> particles);

// The most events a whole run may be estimated to need: about an hour of the
// engine at its slowest. Beyond it a run takes hours, or never ends (a
// moving disk that fills the box, speeds far above the box per step).
inline constexpr double max_estimated_run_events = 2e9;

// The exact engine's two guards against runs that would not end: before the
// run, this one (std::invalid_argument naming the estimate and the limit, or
// past max_exact_steps); during it, TooManyEvents for a single step that
// runs away.
void require_feasible_exact_run(const World& world, std::span<const Particle> particles, std::int64_t steps);

}  // namespace particlesim
