#include "check/exact_step_check.hpp"

#include "check/close_pairs.hpp"
#include "core/physics.hpp"
#include "core/random.hpp"
#include "io/number_format.hpp"
#include "particlesim/exact_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace particlesim {

namespace {

// The printed state and three copies moved within its uncertainty; where a
// step amplifies the rounding (several collisions), sixteen: four samples
// of a spread that collisions stretch unevenly fall short of its extremes
// often enough to call a correct output wrong (a crystal at area fraction
// 0.7 gives each disk about ten collisions a step).
constexpr int ensemble_size = 4;
constexpr int amplifying_ensemble_size = 16;
// The amplification (spread over the shift) from which a step counts as amplifying.
constexpr double amplifying = 8.0;
// Where the program may land, in spreads of the ensemble beyond its extremes:
// three samples underestimate the true spread, a factor 4 covers it.
constexpr double spread_factor = 4.0;
// A perf-mode run is judged only while its ensemble stays this close, in r;
// so is a particle's step whose amplification passes judged_amplification.
constexpr double judged_spread = 1e-3;
// A particle whose step amplifies the printing's rounding more than this,
// and whose copies either disagree on its collisions or part by more than
// judged_spread r, is not judged: in such a step a collision a few 1e-9 from
// grazing may go either way, and a handful of samples cannot say which way
// the program's own state went. A single collision at the default scene's
// speeds (thousands of r a step) amplifies the rounding about 500 times; its
// copies still agree and stay within 1e-5 r, and it is judged.
constexpr double judged_amplification = 1e3;
// The largest shift of the copies, in r, at which a step is judged: beyond
// it (a box of about 1e11 r and more, or 8 decimals for r below about 5e-8)
// the copies are other scenes, not the printed one within its rounding.
constexpr double judged_shift = 0.1;

// How far the copies of a printed number are moved at most: its printing's
// uncertainty, and at least 2^-40 of it (another correct program rounds
// otherwise even from exact numbers).
constexpr double copies_relative_shift = 0x1p-40;
double copy_shift(double uncertainty, double value) {
    return std::max(uncertainty, copies_relative_shift * std::fabs(value));
}

// A step that is not judged, and why: any collision counts are accepted.
StepCheck not_judged(std::string why, std::size_t particles) {
    StepCheck result;
    result.judged = false;
    result.within_rounding.push_back(std::move(why));
    constexpr std::uint64_t any = std::numeric_limits<std::uint64_t>::max();
    result.collisions.assign(particles, {0, any, 0, any});
    return result;
}

}  // namespace

ExactStepCheck::ExactStepCheck(const World& world, Boundary boundary)
    : world_(world), box_(Box::of(world)), boundary_(boundary) {}

template <typename AfterStep>
void ExactStepCheck::run_ensemble(const PrintedState& start, std::int64_t steps, int members, AfterStep after_step) {
    const auto shift = [&](double value) { return copy_shift(start.uncertainty, value); };
    SplitMix64 random(0x5eedULL);
    const auto moved = [&](double value) { return value + (2.0 * random.uniform() - 1.0) * shift(value); };
    std::vector<ExactSimulation> runs;
    std::string refusal;
    refused_copy_.clear();
    for (int member = 0; member < members; ++member) {
        std::vector<Particle> copy(start.particles.begin(), start.particles.end());
        for (Particle& p : copy) {
            p.particle_collisions = p.wall_collisions = 0;
            for (int axis = 0; axis < 2; ++axis) {
                if (member > 0) {
                    p.position[axis] = moved(p.position[axis]);
                    p.velocity[axis] = moved(p.velocity[axis]);
                }
                if (boundary_ == Boundary::periodic) {
                    p.position[axis] = wrap_into_periodic_box(p.position[axis], world_.box_size);
                } else {
                    p.position[axis] = std::clamp(p.position[axis], box_.lower, box_.upper);
                }
            }
        }
        try {
            ExactOptions options;
            options.boundary = boundary_;
            runs.emplace_back(world_, std::move(copy), options);
        } catch (const std::invalid_argument& e) {
            if (refusal.empty()) refusal = e.what();
        }
    }
    if (runs.empty()) throw std::invalid_argument("the exact engine cannot start from this state: " + refusal);
    refused_copy_ = refusal;
    states_.resize(runs.size());
    for (std::int64_t s = 1; s <= steps; ++s) {
        for (std::size_t m = 0; m < runs.size(); ++m) {
            runs[m].step();
            const auto particles = runs[m].particles();
            states_[m].assign(particles.begin(), particles.end());
        }
        if (!after_step(s)) return;
    }
}

void ExactStepCheck::measure_bounds(const PrintedState& start) {
    const std::size_t count = start.particles.size();
    bounds_.lower.assign(count, Particle{});
    bounds_.upper.assign(count, Particle{});
    bounds_.collisions.assign(count, CollisionRange{});
    bounds_.widest = 0.0;
    bounds_.amplification = 0.0;
    bounds_.unjudged.clear();
    const double base = 4.0 * start.uncertainty;
    const double shift = copy_shift(start.uncertainty, world_.box_size);
    for (std::size_t p = 0; p < count; ++p) {
        Particle& lower = bounds_.lower[p];
        Particle& upper = bounds_.upper[p];
        CollisionRange& counts = bounds_.collisions[p];
        lower = upper = states_[0][p];
        counts = {lower.particle_collisions, lower.particle_collisions, lower.wall_collisions, lower.wall_collisions};
        const Vec2 reference = lower.position;
        for (const auto& state : states_) {
            const Particle& q = state[p];
            // In a periodic box, copies either side of an edge (at 19.99999999
            // and 0.00000001 in a box of 20) are a hair apart, not a box.
            const Vec2 position =
                boundary_ == Boundary::periodic
                    ? reference + separation_in(CloseIn::periodic_square, world_.box_size, reference, q.position)
                    : q.position;
            lower.position = lower.position.cwiseMin(position);
            upper.position = upper.position.cwiseMax(position);
            lower.velocity = lower.velocity.cwiseMin(q.velocity);
            upper.velocity = upper.velocity.cwiseMax(q.velocity);
            counts.particle_min = std::min(counts.particle_min, q.particle_collisions);
            counts.particle_max = std::max(counts.particle_max, q.particle_collisions);
            counts.wall_min = std::min(counts.wall_min, q.wall_collisions);
            counts.wall_max = std::max(counts.wall_max, q.wall_collisions);
        }
        const Vec2 position_spread = upper.position - lower.position;
        const Vec2 velocity_spread = upper.velocity - lower.velocity;
        bounds_.widest = std::max(bounds_.widest, position_spread.maxCoeff());
        bounds_.amplification =
            std::max(bounds_.amplification, std::max(position_spread.maxCoeff(), velocity_spread.maxCoeff()) / shift);
        const double spread = std::max(position_spread.maxCoeff(), velocity_spread.maxCoeff());
        const bool counts_agree = counts.particle_min == counts.particle_max && counts.wall_min == counts.wall_max;
        if (states_.size() > 1 && spread > judged_amplification * shift &&
            (!counts_agree || spread > judged_spread * box_.lower)) {
            bounds_.unjudged.push_back(static_cast<std::uint32_t>(p));
            constexpr double anything = std::numeric_limits<double>::infinity();
            lower.position = lower.velocity = Vec2::Constant(-anything);
            upper.position = upper.velocity = Vec2::Constant(anything);
            counts = {0, std::numeric_limits<std::uint64_t>::max(), 0, std::numeric_limits<std::uint64_t>::max()};
            continue;
        }
        const Vec2 margin = Vec2::Constant(base);
        lower.position -= spread_factor * position_spread + margin;
        upper.position += spread_factor * position_spread + margin;
        lower.velocity -= spread_factor * velocity_spread + margin;
        upper.velocity += spread_factor * velocity_spread + margin;
    }
}

StepCheck ExactStepCheck::check(const PrintedState& before, const PrintedState& after) {
    StepCheck result;
    // Hard disks never overlap: a printed overlap deeper than the printing's
    // rounding and the engines' contact tolerance breaks the rules.
    positions_.resize(after.particles.size());
    for (std::size_t p = 0; p < positions_.size(); ++p) positions_[p] = after.particles[p].position;
    const double diameter = 2.0 * box_.lower;
    const double closest = diameter * (1.0 - overlap_tolerance) - 3.0 * after.uncertainty - 0x1p-50 * world_.box_size;
    std::optional<std::pair<std::uint32_t, std::uint32_t>> overlap;
    const CloseIn space = boundary_ == Boundary::periodic ? CloseIn::periodic_square : CloseIn::square;
    for_each_close_pair(positions_, world_.box_size, closest, space, [&](std::uint32_t i, std::uint32_t j) {
        if (!overlap || std::make_pair(i, j) < *overlap) overlap = std::make_pair(i, j);
    });
    if (overlap) {
        const auto [i, j] = *overlap;
        const double distance = separation_in(space, world_.box_size, positions_[i], positions_[j]).norm();
        result.violation = RuleViolation{
            i,
            "particles " + std::to_string(i) + " and " + std::to_string(j) + " overlap: their centres are " +
                format_brief(distance) + " apart, and hard disks never come closer than 2r = " + format_short(diameter),
            after.particles[i], after.particles[i]};
        return result;
    }

    const double shift = copy_shift(before.uncertainty, world_.box_size);
    if (shift > judged_shift * box_.lower) {
        return not_judged("the printed numbers' rounding (" + format_brief(shift) +
                              ") is not small beside r = " + format_short(box_.lower) + ": the step is not judged",
                          after.particles.size());
    }
    run_ensemble(before, 1, ensemble_size, [](std::int64_t) { return true; });
    if (!refused_copy_.empty()) {
        // Fewer copies would bound the step too narrowly (copies within
        // the rounding overlap where it is not small beside r).
        return not_judged("hard disks within the printing's rounding of the printed state overlap (" + refused_copy_ +
                              "): its rounding is not small beside r; the step is not judged",
                          after.particles.size());
    }
    measure_bounds(before);
    if (bounds_.unjudged.empty() && bounds_.amplification > amplifying) {
        run_ensemble(before, 1, amplifying_ensemble_size, [](std::int64_t) { return true; });
        measure_bounds(before);
    }
    if (!bounds_.unjudged.empty()) {
        // One chaotic particle may have met any other in the step: none is judged.
        return not_judged("particle " + std::to_string(bounds_.unjudged.front()) + " (and " +
                              std::to_string(bounds_.unjudged.size() - 1) +
                              " more): hard disks started within rounding of the printed state part by over " +
                              format_brief(judged_amplification) + " times the rounding in this step and either " +
                              "disagree on its collisions or part by over " + format_brief(judged_spread) +
                              " r (chaos); the step is not judged",
                          after.particles.size());
    }
    for (std::uint32_t p = 0; p < after.particles.size(); ++p) {
        const Particle& printed = after.particles[p];
        const auto fits = [&](double value, double lower, double upper) {
            const double slack = after.uncertainty + std::fabs(value) * 0x1p-51;
            return lower - slack <= value && value <= upper + slack;
        };
        bool fine = true;
        for (int axis = 0; axis < 2; ++axis) {
            const double lower = bounds_.lower[p].position[axis], upper = bounds_.upper[p].position[axis];
            double position = printed.position[axis];
            if (boundary_ == Boundary::periodic)  // the image nearest where the runs went
                position = image_nearest(position, 0.5 * (lower + upper), world_.box_size);
            fine = fine && fits(position, lower, upper);
            fine =
                fine && fits(printed.velocity[axis], bounds_.lower[p].velocity[axis], bounds_.upper[p].velocity[axis]);
        }
        if (fine) continue;
        const Particle& expected = states_[0][p];
        const std::uint64_t events = expected.particle_collisions + expected.wall_collisions;
        std::string what =
            "particle " + std::to_string(p) + ": continuous-time hard disks from the printed state before ";
        what += events == 0
                    ? "move it freely in this step (no collision)"
                    : "give it " + std::to_string(expected.particle_collisions) + " collision(s) with disks and " +
                          std::to_string(expected.wall_collisions) + " with walls in this step";
        what += ", and the printed state does not follow";
        result.violation = RuleViolation{p, what, expected, printed};
        return result;
    }
    result.collisions = bounds_.collisions;
    return result;
}

StepChecker::Run ExactStepCheck::run(const PrintedState& start, std::int64_t steps) {
    StepChecker::Run result;
    const double shift = copy_shift(start.uncertainty, world_.box_size);
    if (steps > 0 && shift > judged_shift * box_.lower) {
        result.undecided_from = 1;
        result.undecided_why = "the printed numbers' rounding (" + format_brief(shift) +
                               ") is not small beside r = " + format_short(box_.lower);
        return result;
    }
    run_ensemble(start, steps, ensemble_size, [&](std::int64_t s) {
        if (!refused_copy_.empty()) {
            result.undecided_from = s;
            result.undecided_why = "hard disks within the printing's rounding of the initial state overlap (" +
                                   refused_copy_ + "): its rounding is not small beside r";
            return false;
        }
        measure_bounds(start);
        if (bounds_.widest <= judged_spread * box_.lower) return true;
        result.undecided_from = s;
        result.undecided_why = "hard disks started within the printing's rounding of the initial state are " +
                               format_brief(bounds_.widest) + " apart after step " + std::to_string(s) +
                               " (chaos): the final state cannot be judged from the initial one";
        return false;
    });
    if (steps == 0) {
        states_.assign(1, std::vector<Particle>(start.particles.begin(), start.particles.end()));
        for (Particle& p : states_[0]) p.particle_collisions = p.wall_collisions = 0;
        measure_bounds(start);
    }
    result.lower = bounds_.lower;
    result.upper = bounds_.upper;
    result.collisions = bounds_.collisions;
    return result;
}

}  // namespace particlesim
