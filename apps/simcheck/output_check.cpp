#include "output_check.hpp"

#include "particlesim/random_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace simcheck {

namespace {

using namespace particlesim;

constexpr std::size_t notes_kept = 20;

double slack(double value, double uncertainty) { return uncertainty + std::fabs(value) * 0x1p-51; }

// One block of the output: N lines of `step`, in index order, with counters
// exactly when it is the final block; or what is wrong with its shape.
class BlockReader {
public:
    // Nothing of size N is allocated before N lines have been read: a scene
    // may claim millions of particles over an output of three lines.
    BlockReader(LineSource& output, std::size_t count, bool counters_optional)
        : output_(output), count_(count), counters_optional_(counters_optional) {}

    std::optional<Finding> read(std::int64_t step, bool final_block) {
        particlesim::OutputLine line;
        particles_.clear();
        lines_.clear();
        for (std::size_t i = 0; i < count_; ++i) {
            if (!output_.next(line)) {
                return Finding{step, output_.lines_read(),
                               "the output ends (after line " + std::to_string(output_.lines_read()) +
                                   ") before particle " + std::to_string(i) + " of step " + std::to_string(step),
                               std::nullopt, std::nullopt};
            }
            if (line.step != step || line.index != i) {
                return Finding{step, line.line,
                               "line " + std::to_string(line.line) + " reads " + particlesim::quoted_text(line.text) +
                                   " where particle " + std::to_string(i) + " of step " + std::to_string(step) +
                                   " belongs: a line is missing, repeated or out of order",
                               std::nullopt, std::nullopt};
            }
            if (line.has_counters != final_block && !(final_block && counters_optional_)) {
                return Finding{step, line.line,
                               final_block ? "line " + std::to_string(line.line) +
                                                 " has no counters: the lines of the final block end with pc wc"
                                           : "line " + std::to_string(line.line) +
                                                 " has counters, which only the final block's lines have",
                               std::nullopt, std::nullopt};
            }
            particles_.push_back(line.particle);
            lines_.push_back(line.line);
        }
        return std::nullopt;
    }

    std::optional<Finding> expect_end(std::int64_t last_step) {
        particlesim::OutputLine line;
        if (!output_.next(line)) return std::nullopt;
        return Finding{last_step, line.line,
                       "the output goes on after the final block: line " + std::to_string(line.line) + " reads " +
                           particlesim::quoted_text(line.text),
                       std::nullopt, std::nullopt};
    }

    std::vector<Particle>& particles() { return particles_; }
    [[nodiscard]] long line_of(std::size_t particle) const { return lines_[particle]; }

private:
    LineSource& output_;
    std::size_t count_;
    bool counters_optional_;
    std::vector<Particle> particles_;
    std::vector<long> lines_;
};

std::optional<Finding> check_initial_block(const Scene& scene, const BlockReader& block,
                                           std::span<const Particle> printed, double uncertainty, Boundary boundary) {
    const World& world = scene.world;
    const auto fits = [&](double value, double wanted) {
        return std::fabs(value - wanted) <= slack(value, uncertainty);
    };
    // In a periodic box a position may be printed as its image a side away
    // (19.9999999996 in a box of 20 as 0.00000000): the same place.
    const auto fits_position = [&](double value, double wanted) {
        if (fits(value, wanted)) return true;
        return boundary == Boundary::periodic &&
               (fits(value, wanted - world.box_size) || fits(value, wanted + world.box_size));
    };
    const SpeedRange speeds = default_speed_range(world);
    for (std::size_t i = 0; i < printed.size(); ++i) {
        const Particle& p = printed[i];
        const auto finding = [&](const std::string& what, std::optional<Particle> expected) {
            return Finding{0, block.line_of(i), "particle " + std::to_string(i) + ": " + what, expected, p};
        };
        if (!scene.is_random()) {
            const Particle& given = scene.particles[i];
            if (!(fits_position(p.position.x(), given.position.x()) &&
                  fits_position(p.position.y(), given.position.y()) && fits(p.velocity.x(), given.velocity.x()) &&
                  fits(p.velocity.y(), given.velocity.y()))) {
                return finding("the initial state is not the scene's", given);
            }
            continue;
        }
        for (int axis = 0; axis < 2; ++axis) {
            const double value = p.position[axis];
            if (value < world.lower() - slack(value, uncertainty) ||
                value > world.upper() + slack(value, uncertainty)) {
                return finding("the random start puts it outside [r, L - r]", std::nullopt);
            }
        }
        // rules.md "Random scenes": speeds between L/(8r) and L/4.
        const double speed = p.velocity.norm();
        const double speed_slack = 2.0 * slack(speed, uncertainty);
        if (speed < speeds.min - speed_slack || speed > speeds.max + speed_slack) {
            return finding("its random speed " + std::to_string(speed) + " is outside [" + std::to_string(speeds.min) +
                               ", " + std::to_string(speeds.max) + "], the range of rules.md \"Random scenes\"",
                           std::nullopt);
        }
    }
    return std::nullopt;
}

std::string count_text(std::uint64_t low, std::uint64_t high) {
    return low == high ? std::to_string(low) : "between " + std::to_string(low) + " and " + std::to_string(high);
}

// The final counters against the collisions the rules allow over the run.
std::optional<Finding> check_counters(const BlockReader& block, std::span<const Particle> printed,
                                      std::span<const CollisionRange> totals, std::int64_t step) {
    for (std::size_t i = 0; i < printed.size(); ++i) {
        const CollisionRange& t = totals[i];
        const Particle& p = printed[i];
        std::string what;
        if (p.particle_collisions < t.particle_min || p.particle_collisions > t.particle_max) {
            what = "pc = " + std::to_string(p.particle_collisions) + ", but the rules give it " +
                   count_text(t.particle_min, t.particle_max) + " collisions with particles";
        } else if (p.wall_collisions < t.wall_min || p.wall_collisions > t.wall_max) {
            what = "wc = " + std::to_string(p.wall_collisions) + ", but the rules give it " +
                   count_text(t.wall_min, t.wall_max) + " collisions with walls";
        }
        if (!what.empty()) {
            return Finding{step, block.line_of(i), "particle " + std::to_string(i) + ": the final block's " + what,
                           std::nullopt, std::nullopt};
        }
    }
    return std::nullopt;
}

// An unjudged step may have had any number of collisions: the maximum saturates.
void add_counts(CollisionRange& total, const CollisionRange& step) {
    const auto add = [](std::uint64_t a, std::uint64_t b) {
        return a > std::numeric_limits<std::uint64_t>::max() - b ? std::numeric_limits<std::uint64_t>::max() : a + b;
    };
    total.particle_min = add(total.particle_min, step.particle_min);
    total.particle_max = add(total.particle_max, step.particle_max);
    total.wall_min = add(total.wall_min, step.wall_min);
    total.wall_max = add(total.wall_max, step.wall_max);
}

Report broken(Report report, Finding finding) {
    report.verdict = Verdict::breaks_rules;
    report.finding = std::move(finding);
    return report;
}

void add_notes(Report& report, std::int64_t step, const std::vector<std::string>& notes) {
    for (const std::string& note : notes) {
        if (report.within_rounding.size() < notes_kept) report.within_rounding.emplace_back(step, note);
    }
    report.within_rounding_count += notes.size();
    if (!notes.empty()) report.steps_within_rounding.push_back(step);
}

}  // namespace

Report check_output(const Scene& scene, LineSource& output, const StepCheckOptions& options,
                    const ShapeAllowance& allowance) {
    Report report;
    const std::size_t count = scene.particle_count;
    const std::int64_t steps = scene.steps;
    report.particles = count;
    report.steps = steps;
    report.radius = scene.world.radius;
    StepChecker checker(scene.world, options);

    const bool judge_counters = !allowance.final_block_without_counters;
    BlockReader block(output, count, !judge_counters);
    if (auto wrong = block.read(0, false)) return broken(report, *wrong);
    report.uncertainty = output.uncertainty();
    std::vector<Particle> previous = block.particles();
    if (auto wrong = check_initial_block(scene, block, previous, report.uncertainty, options.boundary))
        return broken(report, *wrong);
    // The first step starts from the scene's own numbers where it lists them.
    double previous_uncertainty = report.uncertainty;
    if (!scene.is_random()) {
        previous = scene.particles;
        previous_uncertainty = 0.0;
    }

    std::vector<CollisionRange> totals(count);  // N lines are read by now
    // The coordinates the last step put exactly on a wall: the next step
    // starts from them exactly (StepCheck::on_wall).
    std::vector<OnWall> previous_on_wall;
    std::int64_t loose_steps = 0, first_loose_step = 0;
    std::string first_loose_why;
    std::string first_unjudged_why;
    const auto compare = [&](std::int64_t step, const StepCheck& check) -> std::optional<Finding> {
        if (check.violation) {
            const RuleViolation& v = *check.violation;
            return Finding{step, block.line_of(v.particle), v.what, v.expected, v.printed};
        }
        if (check.loose) {
            if (loose_steps++ == 0) {
                first_loose_step = step;
                first_loose_why = *check.loose;
            }
        }
        if (check.judged) {
            ++report.steps_judged;
        } else if (first_unjudged_why.empty() && !check.within_rounding.empty()) {
            first_unjudged_why = check.within_rounding.front();
        }
        add_notes(report, step, check.within_rounding);
        for (std::size_t i = 0; i < count; ++i) {
            add_counts(totals[i], check.collisions[i]);
        }
        return std::nullopt;
    };

    if (scene.mode == OutputMode::print && steps > 0) {
        for (std::int64_t step = 1; step <= steps; ++step) {
            if (auto wrong = block.read(step, step == steps)) return broken(report, *wrong);
            StepCheck check = checker.check({previous, previous_uncertainty, previous_on_wall},
                                            {block.particles(), report.uncertainty});
            if (auto wrong = compare(step, check)) return broken(report, *wrong);
            previous.swap(block.particles());
            previous_uncertainty = report.uncertainty;
            previous_on_wall.swap(check.on_wall);
            report.steps_checked = step;
        }
        const std::span<const Particle> last = previous;
        if (judge_counters) {
            if (auto wrong = check_counters(block, last, totals, steps)) return broken(report, *wrong);
        }
        if (auto wrong = block.expect_end(steps)) return broken(report, *wrong);
        if (report.steps_judged == 0) {
            // Every state was accepted: a wrong output would have passed as well.
            report.verdict = Verdict::no_verdict;
            report.reason =
                "no step could be judged (the first: " + first_unjudged_why + "); a wrong output would pass as well";
        } else if (loose_steps > 0) {
            // Bounds that sound never reject a correct state, but too wide to
            // catch every wrong one: no mistake found is not "conforms".
            report.verdict = Verdict::no_verdict;
            report.reason = "no step breaks the rules, but at " + std::to_string(loose_steps) + " of " +
                            std::to_string(steps) + " steps (the first: step " + std::to_string(first_loose_step) +
                            ") a decision within rounding in a micro-step before the last left a disk's bounds "
                            "wider than a diameter: " +
                            first_loose_why +
                            "; there, a wrong state may pass. An output made without substeps is checked strictly";
        }
        return report;
    }

    // perf mode (or no steps): the final block alone, judged from the start.
    if (auto wrong = block.read(steps, true)) return broken(report, *wrong);
    if (auto wrong = block.expect_end(steps)) return broken(report, *wrong);
    const StepChecker::Run run = checker.run({previous, previous_uncertainty}, steps);
    if (run.undecided_from) {
        report.verdict = Verdict::no_verdict;
        report.reason = "a perf-mode output shows only the first and the last state, and from step " +
                        std::to_string(*run.undecided_from) +
                        " on the rules may go more than one way within rounding (" + run.undecided_why +
                        "), so correct programs may end anywhere; a print-mode output of the same scene is checked "
                        "step by step";
        return report;
    }
    const std::vector<Particle>& last = block.particles();
    if (auto violation = checker.final_state_violation(run, {last, report.uncertainty})) {
        return broken(report, Finding{steps, block.line_of(violation->particle), violation->what, violation->expected,
                                      violation->printed});
    }
    if (judge_counters) {
        if (auto wrong = check_counters(block, last, run.collisions, steps)) return broken(report, *wrong);
    }
    return report;
}

}  // namespace simcheck
