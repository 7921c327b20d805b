#pragma once
// The step checker for continuous-time hard disks (simcli --engine exact).
// Event-driven dynamics has no small set of decisions to bound one by one,
// so the tolerance is measured instead: the exact engine is run from the
// printed state and from copies moved within the printing's uncertainty,
// and the printed next state must lie within a wide margin of where they go.

#include "core/box.hpp"
#include "particlesim/step_check.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace particlesim {

class ExactStepCheck {
public:
    ExactStepCheck(const World& world, Boundary boundary);

    [[nodiscard]] StepCheck check(const PrintedState& before, const PrintedState& after);
    [[nodiscard]] StepChecker::Run run(const PrintedState& start, std::int64_t steps);

private:
    struct Bounds {
        std::vector<Particle> lower, upper;
        std::vector<CollisionRange> collisions;
        double widest = 0.0;                  // the largest spread of a position between the runs
        double amplification = 0.0;           // the largest spread of a particle's state over the shift
        std::vector<std::uint32_t> unjudged;  // particles whose step is too chaotic to judge
    };
    // Runs an ensemble of `members` `steps` steps on, calling `after_step(s)` after each.
    template <typename AfterStep>
    void run_ensemble(const PrintedState& start, std::int64_t steps, int members, AfterStep after_step);
    void measure_bounds(const PrintedState& start);

    World world_;
    Box box_;
    Boundary boundary_;
    std::vector<std::vector<Particle>> states_;  // of each run that could start
    // Why a copy within the printing's rounding could not start (two disks
    // overlap): empty when every copy started.
    std::string refused_copy_;
    std::vector<Vec2> positions_;
    Bounds bounds_;
};

}  // namespace particlesim
