#pragma once
// Checks one step of any program's output against the rules, for graders and
// for people writing their own simulator (docs/checking.md). A whole output
// cannot be compared with ours: two correct programs that round differently
// drift apart on a crowded scene within a few dozen steps. So each step is
// judged from the program's own previous printed state: one step of the
// rules is applied to every state within the printing's uncertainty of it,
// and the printed next state must be one they lead to. A decision of the
// rules that lies within that uncertainty (t <= 1, a graze, a tie, a wall
// reached within the rest of the step) allows either outcome.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace particlesim {

// Where the rules put a particle's coordinate on each axis: exactly on the
// lower wall (r: -1), exactly on the upper one (L - r: +1), or not known to
// be on either (0).
struct OnWall {
    std::int8_t x = 0;
    std::int8_t y = 0;
};

// A state as a program printed it (counters are ignored).
struct PrintedState {
    std::span<const Particle> particles;
    // How far each printed number may be from the value the program held:
    // 0.5e-8 for io.md's %.8f, 0 for exact numbers (a scene, --exact-numbers).
    double uncertainty = 0.0;
    // Optional, per particle: the coordinates the step that led here put
    // exactly on a wall (StepCheck::on_wall), known exactly however they
    // were printed. Empty: none.
    std::span<const OnWall> on_wall = {};
};

inline constexpr double fixed8_uncertainty = 0.5e-8;

enum class CheckedRules {
    stepped,  // rules.md "One step" (with substeps)
    exact,    // continuous-time hard disks (simcli --engine exact)
};

struct StepCheckOptions {
    CheckedRules rules = CheckedRules::stepped;
    int substeps = 1;  // micro-steps per step of the stepped rules, >= 1
    // The exact rules in a periodic box (ExactOptions::boundary); the stepped
    // rules have walls.
    Boundary boundary = Boundary::walls;
    // The most pairs of disks that may collide in one step the stepped
    // rules' checker holds (about 64 bytes each); 0: as many as an eighth
    // of the machine's memory holds (49 M with 24 GiB). Disks piled on one
    // another make every pair of the pile one.
    std::size_t most_possible_pairs = 0;
};

// The collisions a particle may have had in the step, as far as decided.
struct CollisionRange {
    std::uint64_t particle_min = 0;
    std::uint64_t particle_max = 0;
    std::uint64_t wall_min = 0;
    std::uint64_t wall_max = 0;
};

struct RuleViolation {
    std::uint32_t particle = 0;
    std::string what;   // in a person's words: "particles 3 and 7 meet at t = 0.4172 and ..."
    Particle expected;  // the middle of what the rules allow
    Particle printed;
};

struct StepCheck {
    std::optional<RuleViolation> violation;  // the first particle the step gets wrong
    // Decisions within the uncertainty, where either outcome was accepted.
    std::vector<std::string> within_rounding;
    // False when the step could not be judged at all (its within_rounding
    // note says why: chaos, or a printing too coarse beside r): any state
    // was accepted.
    bool judged = true;
    // Per particle (when there is no violation).
    std::vector<CollisionRange> collisions;
    // Per particle (stepped rules, when there is no violation): the
    // coordinates that every way of explaining the step leaves exactly on a
    // wall, where the rules set them (a disk stopped at the wall, or hitting
    // it at the step's very end). The next step starts from them exactly
    // (PrintedState::on_wall): a disk printed on the wall is otherwise known
    // only within the printing, and whether its wall hit at t = 0 comes
    // before a pair's is then within rounding.
    std::vector<OnWall> on_wall;
    // With substeps: set when the decisions within rounding in the
    // micro-steps before the last went too many ways to follow each, so
    // their fates were merged into one set of bounds, and a particle's grew
    // wider than a diameter by the step's end (a wall hit at a micro-step's
    // end, taken or not, leaves its velocity known only up to its sign).
    // The step was checked, and a violation found is one, but a wrong state
    // may pass: why, in words.
    std::optional<std::string> loose;
};

class StepChecker {
public:
    // Throws std::invalid_argument for a bad world or option.
    explicit StepChecker(const World& world, const StepCheckOptions& options = {});
    ~StepChecker();
    // Movable; a moved-from StepChecker may only be assigned to or destroyed.
    StepChecker(StepChecker&&) noexcept;
    StepChecker& operator=(StepChecker&&) noexcept;

    // Whether `after` is one step of the rules from `before` (same number of
    // particles, in index order). Throws std::invalid_argument when `before`
    // is not a valid state, or (exact rules) when its disks overlap beyond
    // its uncertainty: no step of the rules starts there; and when either
    // state's uncertainty is negative or NaN, or its on_wall is neither
    // empty nor one per particle. Throws std::runtime_error where more
    // pairs may collide in the step than StepCheckOptions::most_possible_pairs.
    [[nodiscard]] StepCheck check(const PrintedState& before, const PrintedState& after);

    // The stepped rules run for `steps` steps from `start` (a perf-mode
    // output has nothing in between): the bounds of every state they may
    // reach and the collision counts, or the first step from which a decision
    // is within rounding and the run may go more than one way. Throws
    // std::invalid_argument as check() does for `start`, and for steps < 0.
    struct Run {
        std::vector<Particle> lower;  // componentwise bounds of the final state
        std::vector<Particle> upper;
        std::vector<CollisionRange> collisions;  // totals over the run
        std::optional<std::int64_t> undecided_from;
        std::string undecided_why;
        std::int64_t steps = 0;  // as asked of run()
    };
    [[nodiscard]] Run run(const PrintedState& start, std::int64_t steps);

    // Whether `final_state` (a perf-mode output's last block) is where `run`
    // (run() from the output's first block) takes the start: the first
    // particle outside the run's bounds, within the final state's
    // uncertainty, or none. In a periodic box a position is compared at its
    // image nearest the bounds. Throws std::invalid_argument when the run
    // went more than one way (undecided_from: no final state is certain),
    // when the two hold different numbers of particles, and for an
    // uncertainty as check() does.
    [[nodiscard]] std::optional<RuleViolation> final_state_violation(const Run& run,
                                                                     const PrintedState& final_state) const;

private:
    class Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace particlesim
