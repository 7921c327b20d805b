// The library's step checker on hand-built steps worked out on paper (r = 1),
// each with the right next state (accepted) and classic wrong ones (caught,
// with the reason in words), and decisions that lie within rounding.

#include "check.hpp"
#include "disk.hpp"

#include "check/close_pairs.hpp"
#include "check/uncertain_step.hpp"
#include "particlesim/step_check.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace particlesim;

namespace {

using test_scenes::disk;

StepCheck check_exact(double box, const std::vector<Particle>& before, const std::vector<Particle>& after,
                      const StepCheckOptions& options = {}) {
    StepChecker checker(World{box, 1.0}, options);
    return checker.check({before, 0.0}, {after, fixed8_uncertainty});
}

bool says(const StepCheck& check, const std::string& words) {
    return check.violation && check.violation->what.find(words) != std::string::npos;
}

void head_on_pair() {
    // Centres 4 apart closing at 4 per step: contact (distance 2) at t = 0.5,
    // at x = 6 and 8; the velocities swap and each goes back for 0.5.
    const std::vector<Particle> before{disk(5, 10, 2, 0), disk(9, 10, -2, 0)};
    const StepCheck right = check_exact(20, before, {disk(5, 10, -2, 0), disk(9, 10, 2, 0)});
    CHECK(!right.violation);
    CHECK(right.within_rounding.empty());
    CHECK_EQ(right.collisions[0].particle_min, 1U);
    CHECK_EQ(right.collisions[1].particle_max, 1U);
    CHECK_EQ(right.collisions[0].wall_max, 0U);
    // Passing through each other: both at x = 7 with their old velocities.
    const StepCheck passing = check_exact(20, before, {disk(7, 10, 2, 0), disk(7, 10, -2, 0)});
    CHECK(says(passing, "particles 0 and 1 meet at t = 0.5, and the output lets them pass"));
    CHECK_EQ(passing.violation->particle, 0U);
    CHECK_EQ(passing.violation->expected.position.x(), 5.0);
    // Off by 1e-6 in one coordinate: beyond the printing's 5e-9.
    const StepCheck off = check_exact(20, before, {disk(5, 10, -2, 0), disk(9, 10.000001, 2, 0)});
    CHECK(off.violation && off.violation->particle == 1);
    // Within the printing: 3e-9 off.
    CHECK(!check_exact(20, before, {disk(5, 10, -2, 0), disk(9, 10.000000003, 2, 0)}).violation);
}

void stop_at_the_wall() {
    // Disk 0 at x = 5 moving -2 meets disk 1 resting at x = 2 at t = 0.5 (x = 4
    // and 2); disk 1 takes the velocity -2 and reaches the wall x = 1 at
    // exactly the end of the step: it stops there, velocity unchanged.
    const std::vector<Particle> before{disk(5, 52, -2, 0), disk(2, 52, 0, 0)};
    CHECK(!check_exact(64, before, {disk(4, 52, 0, 0), disk(1, 52, -2, 0)}).violation);
    // Reflected at once instead of stopping.
    const StepCheck reflected = check_exact(64, before, {disk(4, 52, 0, 0), disk(1, 52, 2, 0)});
    CHECK(says(reflected, "must stop at the wall (x = 1) and bounce at t = 0 of the next step"));
    CHECK_EQ(reflected.violation->particle, 1U);
}

void exact_corner() {
    // From (2, 2) at (-2, -2) the corner (1, 1) is reached at t = 0.5 on both
    // axes: both components flip, and the rest of the step brings it back.
    const std::vector<Particle> before{disk(2, 2, -2, -2)};
    const StepCheck right = check_exact(64, before, {disk(2, 2, 2, 2)});
    CHECK(!right.violation);
    CHECK_EQ(right.collisions[0].wall_min, 1U);
    // Only vx flipped: it then sits on the bottom wall (stopped there).
    const StepCheck one_axis = check_exact(64, before, {disk(2, 1, 2, -2)});
    CHECK(says(one_axis, "reaches the corner at t = 0.5: both vx and vy flip, but the output flips only vx"));
}

void wall_wins_a_tie() {
    // Disk 0 reaches the wall x = 1 at t = 0.5, and disk 1 (from (1, 11)
    // downwards) touches it there at the same time: the wall comes first, so
    // disk 0 bounces back to (2, 8) and disk 1 passes on to (1, 9).
    const std::vector<Particle> before{disk(2, 8, -2, 0), disk(1, 11, 0, -2)};
    CHECK(!check_exact(64, before, {disk(2, 8, 2, 0), disk(1, 9, 0, -2)}).violation);
    // The pair first: at contact (1, 8) and (1, 10) the normal is vertical, so
    // disk 0 keeps vx = -2 and takes vy = -2, disk 1 stops; disk 0 sits on the
    // wall x = 1 moving into it, so it stops there at once (1, 8).
    const StepCheck pair_first = check_exact(64, before, {disk(1, 8, -2, -2), disk(1, 10, 0, 0)});
    CHECK(says(pair_first, "the output carries out another collision first"));
    CHECK(says(pair_first, "a tie"));
}

void lowest_indices_win() {
    // Disk 0 rests at x = 32; disks 1 and 2 reach it from both sides at t = 0.5.
    // Pair (0, 1) comes first: 0 takes +2 and passes into disk 2's path; disk
    // 2 is free and moves on to x = 33, overlapping disk 0 (left for the next step).
    const std::vector<Particle> before{disk(32, 32, 0, 0), disk(29, 32, 2, 0), disk(35, 32, -2, 0)};
    CHECK(!check_exact(64, before, {disk(33, 32, 2, 0), disk(30, 32, 0, 0), disk(33, 32, -2, 0)}).violation);
    const StepCheck wrong = check_exact(64, before, {disk(31, 32, -2, 0), disk(31, 32, 2, 0), disk(34, 32, 0, 0)});
    CHECK(wrong.violation.has_value());
}

void overlapping_pair_collides_at_zero() {
    // Centres 1.5 apart, approaching: a collision at t = 0 (rules.md, C <= 0).
    // At t = 0 the velocities swap along x, then each moves a whole step.
    const std::vector<Particle> before{disk(10, 10, 1, 0), disk(11.5, 10, -1, 0)};
    CHECK(!check_exact(20, before, {disk(9, 10, -1, 0), disk(12.5, 10, 1, 0)}).violation);
    const StepCheck never = check_exact(20, before, {disk(11, 10, 1, 0), disk(10.5, 10, -1, 0)});
    CHECK(says(never, "overlap at the start of the step and approach each other, so they collide at t = 0"));
}

void contact_at_t_one_within_rounding() {
    // Printed centres 4 apart closing at 2 per step: contact at t = 1, but the
    // printed numbers are known within 5e-9, so t may be just beyond 1: both
    // the collision (velocities swapped at x = 11 and 13) and none are right.
    const std::vector<Particle> before{disk(10, 10, 1, 0), disk(14, 10, -1, 0)};
    StepChecker checker(World{40, 1.0});
    const StepCheck collided = checker.check(
        {before, fixed8_uncertainty}, {std::vector{disk(11, 10, -1, 0), disk(13, 10, 1, 0)}, fixed8_uncertainty});
    const StepCheck passed = checker.check({before, fixed8_uncertainty},
                                           {std::vector{disk(11, 10, 1, 0), disk(13, 10, -1, 0)}, fixed8_uncertainty});
    CHECK(!collided.violation);
    CHECK(!passed.violation);
    CHECK(!passed.within_rounding.empty());
    CHECK_EQ(passed.collisions[0].particle_max, 0U);
    CHECK_EQ(collided.collisions[0].particle_min, 1U);
    // From exact numbers t = 1 is decided: the contact is a candidate.
    const StepCheck exact_passed =
        checker.check({before, 0.0}, {std::vector{disk(11, 10, 1, 0), disk(13, 10, -1, 0)}, fixed8_uncertainty});
    CHECK(says(exact_passed, "meet at t = 1, and the output lets them pass"));
}

void substeps() {
    // Disk 0 at x = 2 moving -2 bounces off the wall x = 1 at t = 0.5; disk 1
    // rests at x = 4. In one step that is disk 0's one collision: it goes back
    // to x = 2 and passes into disk 1's place. In two micro-steps of 0.5, the
    // second starts with disk 0 at x = 1 moving +2, 3 from disk 1: they touch at
    // its end (t = 0.5) and swap velocities.
    const std::vector<Particle> before{disk(2, 10, -2, 0), disk(4, 10, 0, 0)};
    const std::vector<Particle> one_collision{disk(2, 10, 2, 0), disk(4, 10, 0, 0)};
    const std::vector<Particle> two_collisions{disk(2, 10, 0, 0), disk(4, 10, 2, 0)};
    StepChecker whole(World{20, 1.0});
    StepChecker halves(World{20, 1.0}, {CheckedRules::stepped, 2});
    CHECK(!whole.check({before, 0.0}, {one_collision, fixed8_uncertainty}).violation);
    CHECK(whole.check({before, 0.0}, {two_collisions, fixed8_uncertainty}).violation.has_value());
    const StepCheck split = halves.check({before, 0.0}, {two_collisions, fixed8_uncertainty});
    CHECK(!split.violation);
    CHECK_EQ(split.collisions[0].wall_min, 1U);
    CHECK_EQ(split.collisions[0].particle_min, 1U);
    CHECK(halves.check({before, 0.0}, {one_collision, fixed8_uncertainty}).violation.has_value());
}

void wall_hit_at_a_micro_step_end() {
    // Disk 0 at x = 2 moving -2 reaches the wall x = 1 at t = 0.5, the end of
    // the first of two micro-steps. Printed (known within 5e-9), the hit may
    // fall in either micro-step: bounced at the end of the first, or stopped
    // there and bounced at t = 0 of the second. Both end at x = 2 moving +2
    // with one wall hit, and the checker follows both instead of merging
    // velocities -2 and +2 into one bound: strict, and 1 r off is caught.
    const std::vector<Particle> before{disk(2, 10, -2, 0), disk(15, 10, 0, 0)};
    StepChecker halves(World{20, 1.0}, {CheckedRules::stepped, 2});
    const StepCheck right = halves.check({before, fixed8_uncertainty},
                                         {std::vector{disk(2, 10, 2, 0), disk(15, 10, 0, 0)}, fixed8_uncertainty});
    CHECK(!right.violation);
    CHECK(!right.loose);
    CHECK_EQ(right.collisions[0].wall_min, 1U);
    CHECK_EQ(right.collisions[0].wall_max, 1U);
    CHECK(!right.within_rounding.empty());
    const StepCheck off = halves.check({before, fixed8_uncertainty},
                                       {std::vector{disk(3, 10, 2, 0), disk(15, 10, 0, 0)}, fixed8_uncertainty});
    CHECK(off.violation && off.violation->particle == 0);
    const StepCheck unbounced = halves.check({before, fixed8_uncertainty},
                                             {std::vector{disk(1, 10, -2, 0), disk(15, 10, 0, 0)}, fixed8_uncertainty});
    CHECK(unbounced.violation.has_value());
}

void sure_wall_hit_is_never_free() {
    // Disk 0 at x = 12 moving +8 meets disk 1, resting at x = 16, at t = 0.25;
    // so does disk 2, coming down at -8 from y = 14: an exact tie, which the
    // printing turns into one within rounding. If disk 1 takes disk 2, disk 0
    // reaches the wall x = 19 at t = 0.875 and bounces back to x = 18. Either
    // way disk 0 collides: it cannot end the step unbounced at the wall.
    const std::vector<Particle> before{disk(12, 10, 8, 0), disk(16, 10, 0, 0), disk(16, 14, 0, -8)};
    StepChecker checker(World{20, 1.0});
    const auto check_after = [&](const std::vector<Particle>& after) {
        return checker.check({before, fixed8_uncertainty}, {after, fixed8_uncertainty});
    };
    const StepCheck first_pair = check_after({disk(14, 10, 0, 0), disk(19, 10, 8, 0), disk(16, 6, 0, -8)});
    CHECK(!first_pair.violation);
    const StepCheck second_pair = check_after({disk(18, 10, -8, 0), disk(16, 4, 0, -8), disk(16, 12, 0, 0)});
    CHECK(!second_pair.violation);
    CHECK_EQ(second_pair.collisions[0].wall_min, 1U);
    const StepCheck unbounced = check_after({disk(19, 10, 8, 0), disk(16, 4, 0, -8), disk(16, 12, 0, 0)});
    CHECK(unbounced.violation && unbounced.violation->particle == 0);
}

void creeping_along_a_wall() {
    // Disk 0 slides down the wall x = 1 (vx printed 0, so its sign is within
    // rounding); the floor y = 1 is 4.5 steps away. In this step it may touch
    // the wall it slides on, to no effect, but cannot bounce off the floor.
    const std::vector<Particle> before{disk(1, 10, 0, -2), disk(15, 15, 0, 0)};
    StepChecker checker(World{20, 1.0});
    const auto check_after = [&](const std::vector<Particle>& after) {
        return checker.check({before, fixed8_uncertainty}, {after, fixed8_uncertainty});
    };
    CHECK(!check_after({disk(1, 8, 0, -2), disk(15, 15, 0, 0)}).violation);
    const StepCheck bounced = check_after({disk(1, 2, 0, 2), disk(15, 15, 0, 0)});
    CHECK(bounced.violation && bounced.violation->particle == 0);
}

void either_wall_within_wide_bounds() {
    // Bounds merged from several fates may allow real speeds both ways:
    // x in [1, 98.5], vx in [-100, 100], in a micro-step of 0.1 (L = 100). A
    // wall hit may then be on either side: from x = 98.5 at +100 the disk
    // reaches x = 99 at t = 0.005 and comes back to 99 - 9.5 = 89.5.
    const Box box = Box::of(World{100, 1.0});
    UncertainStep step(box);
    const std::vector<UncertainParticle> state{
        {Uncertain{1, 98.5}, Uncertain::exact(50), Uncertain{-100, 100}, Uncertain::exact(0)}};
    step.predict(state, 0.1);
    int wall = -1;
    for (std::size_t k = 0; k < step.candidates().size(); ++k) {
        if (step.candidates()[k].kind == CollisionKind::wall) wall = static_cast<int>(k);
    }
    CHECK(wall >= 0);
    const UncertainParticle hit = step.outcome(0, wall);
    CHECK(hit.x.lo <= 89.5 && 89.5 <= hit.x.hi);
    CHECK(hit.vx.lo <= -100.0);
}

void starts_on_the_wall_exactly() {
    // The rules put a disk stopped at a wall exactly on it (x = r), and the
    // checker says so (StepCheck::on_wall): here disk 1 stops at x = 1.
    const std::vector<Particle> stopping{disk(5, 52, -2, 0), disk(2, 52, 0, 0)};
    const StepCheck stopped = check_exact(64, stopping, {disk(4, 52, 0, 0), disk(1, 52, -2, 0)});
    CHECK(!stopped.violation);
    CHECK_EQ(static_cast<int>(stopped.on_wall[1].x), -1);
    CHECK_EQ(static_cast<int>(stopped.on_wall[1].y), 0);
    CHECK_EQ(static_cast<int>(stopped.on_wall[0].x), 0);
    // The next step: disk 0 on the wall x = 1 moving into it, disk 1
    // overlapping it (centres 1.5 apart) and approaching. From x = 1 exactly
    // both hit at t = 0 and the wall comes first: disk 0 bounces to x = 3,
    // disk 1 reaches the wall at t = 0.5 and comes back to 2.5. Were disk 0
    // a hair inside, the pair would come first (velocities swapped, both
    // stopping at the wall): printed as 1.00000000, either is within
    // rounding, unless the step before put it there exactly.
    const std::vector<Particle> before{disk(1, 10, -2, 0), disk(2.5, 10, -3, 0)};
    const std::vector<Particle> wall_first{disk(3, 10, 2, 0), disk(2.5, 10, 3, 0)};
    const std::vector<Particle> pair_first{disk(1, 10, -3, 0), disk(1, 10, -2, 0)};
    StepChecker checker(World{20, 1.0});
    const std::vector<OnWall> on_wall{{-1, 0}, {0, 0}};
    CHECK(!checker.check({before, fixed8_uncertainty, on_wall}, {wall_first, fixed8_uncertainty}).violation);
    const StepCheck pair = checker.check({before, fixed8_uncertainty, on_wall}, {pair_first, fixed8_uncertainty});
    CHECK(pair.violation && pair.violation->particle == 0);
    CHECK(!checker.check({before, fixed8_uncertainty}, {pair_first, fixed8_uncertainty}).violation);
    CHECK(!checker.check({before, fixed8_uncertainty}, {wall_first, fixed8_uncertainty}).violation);
}

void outside_the_box() {
    const StepCheck outside = check_exact(20, {disk(10, 18, 0, 3)}, {disk(10, 21, 0, 3)});
    CHECK(says(outside, "particle 0 is outside the box: y = 21 is beyond L - r = 19"));
}

void exact_rules() {
    // Continuous time: disk 0 meets disk 1 at t = 0.5 and stops; disk 1 takes
    // -2 from x = 2 and reaches the wall x = 1 at exactly t = 1, the end of the
    // step: bounced or not yet, both are hard disks within rounding.
    const std::vector<Particle> before{disk(5, 52, -2, 0), disk(2, 52, 0, 0)};
    StepChecker checker(World{64, 1.0}, {CheckedRules::exact, 1});
    CHECK(!checker.check({before, 0.0}, {std::vector{disk(4, 52, 0, 0), disk(1, 52, 2, 0)}, fixed8_uncertainty})
               .violation);
    CHECK(!checker.check({before, 0.0}, {std::vector{disk(4, 52, 0, 0), disk(1, 52, -2, 0)}, fixed8_uncertainty})
               .violation);
    // Passing through each other is not hard disks.
    const StepCheck passing =
        checker.check({before, 0.0}, {std::vector{disk(3, 52, -2, 0), disk(2, 52, 0, 0)}, fixed8_uncertainty});
    CHECK(passing.violation.has_value());
    // Nor is an overlap deeper than rounding.
    const StepCheck overlap = checker.check({std::vector{disk(10, 10, 0, 0), disk(12, 10, 0, 0)}, 0.0},
                                            {std::vector{disk(10, 10, 0, 0), disk(11, 10, 0, 0)}, fixed8_uncertainty});
    CHECK(says(overlap, "particles 0 and 1 overlap"));
}

void perf_run() {
    // Head-on pair over 3 steps, all decided from exact numbers.
    StepChecker checker(World{20, 1.0});
    const StepChecker::Run run = checker.run({std::vector{disk(5, 10, 2, 0), disk(9, 10, -2, 0)}, 0.0}, 3);
    CHECK(!run.undecided_from);
    CHECK_EQ(run.lower[0].position.x(), 1.0);  // x = 5, then bounced: 5 -> 3 -> 1 (stopped on the wall)
    CHECK_EQ(run.collisions[0].particle_min, 1U);
    CHECK_EQ(run.steps, 3);

    // A perf-mode output's last block against the run: the run's own state
    // passes, in %.8f too; a coordinate 1e-6 off is caught at its particle,
    // with the run's state as the expected one.
    const std::vector<Particle> final_state = run.lower;
    CHECK(!checker.final_state_violation(run, {final_state, 0.0}));
    CHECK(!checker.final_state_violation(run, {final_state, fixed8_uncertainty}));
    std::vector<Particle> off = final_state;
    off[1].position.y() += 1e-6;
    const std::optional<RuleViolation> caught = checker.final_state_violation(run, {off, fixed8_uncertainty});
    CHECK(caught && caught->particle == 1);
    CHECK(caught && caught->what ==
                        "particle 1: the final state is not where the rules take it after 3 steps "
                        "(every decision on the way is decided)");
    CHECK(caught && caught->expected.position == final_state[1].position);
    CHECK(caught && caught->printed.position == off[1].position);
    off = final_state;
    off[0].velocity.x() = -off[0].velocity.x();  // a wall hit the other way
    CHECK(checker.final_state_violation(run, {off, fixed8_uncertainty}).has_value());
    off = final_state;
    off[1].position.y() += 3e-9;  // within the printing
    CHECK(!checker.final_state_violation(run, {off, fixed8_uncertainty}));

    // What cannot be compared throws: a run that went more than one way,
    // a state of another size, an uncertainty that is no distance.
    const auto refusal = [&](const StepChecker::Run& compared, const PrintedState& state) {
        try {
            (void)checker.final_state_violation(compared, state);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    StepChecker::Run undecided = run;
    undecided.undecided_from = 2;
    CHECK_EQ(refusal(undecided, {final_state, 0.0}),
             "StepChecker::final_state_violation: the run may go more than one way from step 2, so no final state "
             "is certain");
    CHECK_EQ(refusal(run, {std::vector{final_state[0]}, 0.0}),
             "StepChecker::final_state_violation: the run has 2 particles and the final state 1");
    CHECK_EQ(refusal(run, {final_state, -1.0}),
             "StepChecker: the state after the step has an uncertainty that is not a distance in [0, 1e60]: -1");
}

// In a periodic box the final state is compared at the image nearest the
// run's bounds: a disk at x = 10 moving 10 a step ends one step later on the
// edge, x = 20, printed as its image 0.
void perf_run_across_the_periodic_edge() {
    StepChecker checker(World{20, 1.0}, {.rules = CheckedRules::exact, .boundary = Boundary::periodic});
    const StepChecker::Run run = checker.run({std::vector{disk(10, 10, 10, 0)}, 0.0}, 1);
    CHECK(!run.undecided_from);
    const double end = run.lower[0].position.x();
    CHECK(std::fabs(end - 20.0) < 1e-9 || std::fabs(end) < 1e-9);  // either side of the edge, within the run's rounding
    CHECK(!checker.final_state_violation(run, {std::vector{disk(0, 10, 10, 0)}, fixed8_uncertainty}));
    CHECK(!checker.final_state_violation(run, {std::vector{disk(19.999999999, 10, 10, 0)}, fixed8_uncertainty}));
    const std::optional<RuleViolation> half_off =
        checker.final_state_violation(run, {std::vector{disk(0.5, 10, 10, 0)}, fixed8_uncertainty});
    CHECK(half_off && half_off->particle == 0);
    CHECK(checker.final_state_violation(run, {std::vector{disk(19.5, 10, 10, 0)}, fixed8_uncertainty}).has_value());
}

// What the caller says of a printing is checked too: an uncertainty that is
// no distance, or wall marks for some particles only, throw instead of
// judging (a negative uncertainty would make a right step wrong; marks for
// some particles would be dropped without a word).
void printings_are_checked() {
    const std::vector<Particle> before{disk(5, 10, 1, 0)};
    const std::vector<Particle> after{disk(6, 10, 1, 0)};
    const std::vector<Particle> two{disk(5, 10, 1, 0), disk(15, 10, 0, 0)};
    const std::vector<OnWall> one_mark(1);
    for (const bool exact : {false, true}) {
        const check::Context context(exact ? "exact rules" : "stepped rules");
        StepChecker checker(World{20, 1.0}, {.rules = exact ? CheckedRules::exact : CheckedRules::stepped});
        const auto refusal = [&](const PrintedState& from, const PrintedState& to) {
            try {
                (void)checker.check(from, to);
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
            return std::string();
        };
        CHECK_EQ(refusal({before, 0.0}, {after, fixed8_uncertainty}), "");
        CHECK_EQ(refusal({before, -1.0}, {after, 0.0}),
                 "StepChecker: the state before the step has an uncertainty that is not a distance in [0, 1e60]: -1");
        CHECK_EQ(refusal({before, 0.0}, {after, std::numeric_limits<double>::quiet_NaN()}),
                 "StepChecker: the state after the step has an uncertainty that is not a distance in [0, 1e60]: nan");
        CHECK_EQ(refusal({two, 0.0, one_mark}, {two, 0.0}),
                 "StepChecker: the state before the step has 2 particles and 1 on_wall marks; give one a particle, or "
                 "none");
        CHECK_EQ(refusal({before, 0.0, one_mark}, {after, 0.0}), "");
        bool refused = false;
        try {
            (void)checker.run({before, 0.0}, -1);
        } catch (const std::invalid_argument& e) {
            refused = std::string(e.what()) == "StepChecker::run: steps must be >= 0, not -1";
        }
        CHECK(refused);
    }
}

// The checker's overlap and candidate search against every pair, with
// points on the sides and corners and grids of one to many cells a side: in
// a periodic square, pairs across the sides are as close as they look there.
void close_pairs_against_every_pair() {
    std::mt19937_64 random(7);
    for (int trial = 0; trial < 300; ++trial) {
        const double extent = trial % 3 == 0 ? 1.0 : 100.0;
        const double reach = extent * std::pow(10.0, -2.0 + 2.3 * static_cast<double>(trial % 11) / 10.0);
        const int count = 1 + static_cast<int>(random() % 120);
        std::uniform_real_distribution<double> anywhere(0.0, extent);
        std::vector<Vec2> points;
        for (int k = 0; k < count; ++k) {
            Vec2 p(anywhere(random), anywhere(random));
            if (random() % 5 == 0) p.x() = random() % 2 == 0 ? 0.0 : std::nextafter(extent, 0.0);
            if (random() % 5 == 0) p.y() = random() % 2 == 0 ? 0.0 : std::nextafter(extent, 0.0);
            points.push_back(p);
        }
        for (const CloseIn space : {CloseIn::square, CloseIn::periodic_square}) {
            const bool periodic = space == CloseIn::periodic_square;
            const check::Context context("trial ", trial, periodic ? ", periodic" : ", walls", ", ", count,
                                         " points, reach ", reach);
            std::vector<std::pair<std::uint32_t, std::uint32_t>> found, every;
            for_each_close_pair(points, extent, reach, space,
                                [&](std::uint32_t i, std::uint32_t j) { found.emplace_back(i, j); });
            for (std::uint32_t i = 0; i < points.size(); ++i) {
                for (std::uint32_t j = i + 1; j < points.size(); ++j) {
                    Vec2 d = points[j] - points[i];
                    if (periodic) d = d.cwiseAbs().cwiseMin((Vec2::Constant(extent) - d.cwiseAbs()));
                    if (d.squaredNorm() <= reach * reach) every.emplace_back(i, j);
                }
            }
            const std::size_t visits = found.size();
            std::sort(found.begin(), found.end());
            CHECK(std::unique(found.begin(), found.end()) == found.end());  // each pair once
            CHECK_EQ(visits, every.size());
            CHECK(found == every);
        }
    }
    // Two disks either side of a periodic square's edge, worked out by hand.
    const std::vector<Vec2> across{Vec2(0.5, 5.0), Vec2(19.8, 5.0), Vec2(10.0, 19.9), Vec2(10.0, 0.2)};
    std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
    for_each_close_pair(across, 20.0, 2.0, CloseIn::periodic_square,
                        [&](std::uint32_t i, std::uint32_t j) { found.emplace_back(i, j); });
    CHECK(found == (std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}, {2, 3}}));
    CHECK(std::abs(separation_in(CloseIn::periodic_square, 20.0, across[0], across[1]).x() + 0.7) < 1e-12);
    found.clear();
    for_each_close_pair(across, 20.0, 2.0, CloseIn::square,
                        [&](std::uint32_t i, std::uint32_t j) { found.emplace_back(i, j); });
    CHECK(found.empty());
}

// 300 disks piled on one point: each of their 44 850 pairs may collide.
// Under a limit of 40 000 possible pairs the checker refuses the step in
// words (no verdict, rather than memory without end: a pile of k disks
// takes about 100 k^2 / 2 bytes); under 50 000 it judges the engine's step.
void a_pile_past_the_most_pairs() {
    const World world{2000.0, 1.0};
    std::vector<Particle> pile;
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> offset(-1e-9, 1e-9);
    std::uniform_real_distribution<double> speed(-5.0, 5.0);
    for (int k = 0; k < 300; ++k) pile.push_back(disk(100 + offset(rng), 100 + offset(rng), speed(rng), speed(rng)));
    SteppedSimulation engine(world, pile);
    engine.step();
    const std::vector<Particle> after(engine.particles().begin(), engine.particles().end());
    StepChecker roomy(world, {.most_possible_pairs = 50000});
    CHECK(!roomy.check({pile, 0.0}, {after, 0.0}).violation);
    StepChecker tight(world, {.most_possible_pairs = 40000});
    std::string refusal;
    try {
        (void)tight.check({pile, 0.0}, {after, 0.0});
    } catch (const std::runtime_error& e) {
        refusal = e.what();
    }
    CHECK(refusal.find("more than 40000 pairs of disks may collide in one step") != std::string::npos);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_step_check",
                      {{"head-on pair", head_on_pair},
                       {"stop at the wall", stop_at_the_wall},
                       {"exact corner", exact_corner},
                       {"wall wins a tie", wall_wins_a_tie},
                       {"lowest indices win", lowest_indices_win},
                       {"overlapping pair collides at t = 0", overlapping_pair_collides_at_zero},
                       {"contact at t = 1 within rounding", contact_at_t_one_within_rounding},
                       {"substeps", substeps},
                       {"wall hit at a micro-step's end", wall_hit_at_a_micro_step_end},
                       {"a sure wall hit is never free", sure_wall_hit_is_never_free},
                       {"creeping along a wall", creeping_along_a_wall},
                       {"either wall within wide bounds", either_wall_within_wide_bounds},
                       {"starts on the wall exactly", starts_on_the_wall_exactly},
                       {"outside the box", outside_the_box},
                       {"exact rules", exact_rules},
                       {"perf run", perf_run},
                       {"perf run across the periodic edge", perf_run_across_the_periodic_edge},
                       {"printings are checked", printings_are_checked},
                       {"close pairs against every pair", close_pairs_against_every_pair},
                       {"a pile past the most pairs", a_pile_past_the_most_pairs}});
}
