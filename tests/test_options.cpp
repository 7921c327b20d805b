// Options are checked where they enter an engine or the step checker: every
// bad value throws std::invalid_argument naming the option, and every good
// one is accepted. So are the files and runs given to the library's writers,
// readers and recorders.

#include "check.hpp"

#include "particlesim/accuracy.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/output_reader.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/step_check.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <limits>
#include <stdexcept>
#include <string>

using namespace particlesim;

namespace {

const World world{20.0, 1.0};

std::vector<Particle> two_disks() {
    std::vector<Particle> particles(2);
    particles[0].position = Vec2(5, 5);
    particles[0].velocity = Vec2(1, 0);
    particles[1].position = Vec2(15, 5);
    return particles;
}

// The message of the std::invalid_argument thrown while building, or "" when none is.
template <typename Build>
std::string refusal(Build&& build) {
    try {
        build();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

bool names(const std::string& message, const char* option) { return message.find(option) != std::string::npos; }

void stepped_options_are_checked() {
    const auto stepped = [](const SteppedOptions& options) {
        return refusal([&] { SteppedSimulation(world, two_disks(), options); });
    };
    CHECK(names(stepped({.threads = 0}), "threads"));
    CHECK(names(stepped({.threads = -3}), "threads"));
    // Each thread keeps buffers: two million of them would hold 3 GB for a scene of 32000 disks.
    CHECK_EQ(stepped({.threads = max_threads + 1}),
             "particlesim::SteppedOptions: threads must be in [1, 1024], not 1025");
    CHECK(names(stepped({.substeps = 0}), "substeps"));
    CHECK(names(stepped({.sort_by_position_every = -1}), "sort_by_position_every"));
    CHECK(names(stepped({.pair_search = PairSearch::grid, .grid_cells = 0}), "grid_cells"));
    CHECK(names(stepped({.pair_search = PairSearch::grid, .grid_cells = max_grid_cells + 1}), "grid_cells"));
    // A grid size means nothing to another search: refused, not silently ignored or obeyed.
    CHECK(names(stepped({.pair_search = PairSearch::brute_force, .grid_cells = 4}), "grid_cells"));
    CHECK(names(stepped({.grid_cells = 4}), "grid_cells"));
    CHECK(names(stepped({.substeps = 0}), "SteppedOptions"));
    // A value cast from a number that names no search.
    CHECK_EQ(stepped({.pair_search = static_cast<PairSearch>(7)}),
             "particlesim::SteppedOptions: pair_search must be one of the PairSearch values, not 7");

    CHECK_EQ(stepped({}), "");
    CHECK_EQ(stepped({.pair_search = PairSearch::grid, .grid_cells = max_grid_cells}), "");
    CHECK_EQ(stepped({.pair_search = PairSearch::grid,
                      .grid_cells = 1,
                      .threads = 3,
                      .substeps = 7,
                      .sort_by_position_every = 0}),
             "");
}

void exact_options_are_checked() {
    const auto exact = [](const ExactOptions& options) {
        return refusal([&] { ExactSimulation(world, two_disks(), options); });
    };
    CHECK(names(exact({.cells_per_side = 0}), "cells_per_side"));
    CHECK(names(exact({.cells_per_side = max_grid_cells + 1}), "cells_per_side"));
    CHECK_EQ(exact({.boundary = static_cast<Boundary>(9)}),
             "particlesim::ExactOptions: boundary must be Boundary::walls or Boundary::periodic, not 9");
    CHECK_EQ(exact({}), "");
    CHECK_EQ(exact({.cells_per_side = 1}), "");
}

void bad_worlds_are_refused_by_both_engines() {
    for (const World bad : {World{0.0, 1.0}, World{20.0, 0.0}, World{2.0, 1.5}, World{-1.0, 1.0}}) {
        const check::Context context("L = ", bad.box_size, ", r = ", bad.radius);
        CHECK(!refusal([&] { SteppedSimulation(bad, {}); }).empty());
        CHECK(!refusal([&] { ExactSimulation(bad, {}); }).empty());
    }
    std::vector<Particle> outside = two_disks();
    outside[1].position.x() = 19.5;  // beyond L - r
    CHECK(names(refusal([&] { SteppedSimulation(world, outside); }), "particle 1"));
    CHECK(names(refusal([&] { ExactSimulation(world, outside); }), "particle 1"));
    // NaN is named as such, not as a number out of range.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<Particle> nan_velocity = two_disks();
    nan_velocity[1].velocity.y() = nan;
    std::vector<Particle> nan_position = two_disks();
    nan_position[0].position.x() = nan;
    CHECK_EQ(refusal([&] { SteppedSimulation(world, nan_velocity); }),
             "particlesim::SteppedSimulation: particle 1 has a velocity that is not a number (NaN)");
    CHECK_EQ(refusal([&] { ExactSimulation(world, nan_velocity); }),
             "particlesim::ExactSimulation: particle 1 has a velocity that is not a number (NaN)");
    CHECK_EQ(refusal([&] { ExactSimulation(world, nan_position, {.boundary = Boundary::periodic}); }),
             "particlesim::ExactSimulation: particle 0 has a position that is not a number (NaN)");
}

void step_check_options_are_checked() {
    const auto checker = [](const StepCheckOptions& options) { return refusal([&] { StepChecker(world, options); }); };
    CHECK_EQ(checker({}), "");
    CHECK_EQ(checker({.rules = CheckedRules::exact, .boundary = Boundary::periodic}), "");
    CHECK(names(checker({.substeps = 0}), "substeps"));
    CHECK_EQ(checker({.rules = static_cast<CheckedRules>(5)}),
             "StepCheckOptions: rules must be CheckedRules::stepped or CheckedRules::exact, not 5");
    CHECK_EQ(checker({.rules = CheckedRules::exact, .boundary = static_cast<Boundary>(3)}),
             "StepCheckOptions: boundary must be Boundary::walls or Boundary::periodic, not 3");
}

void null_files_and_mismatched_runs_are_refused() {
    CHECK_EQ(refusal([] { StateWriter(nullptr); }), "particlesim::StateWriter: no FILE to write to (null)");
    CHECK_EQ(refusal([] { OutputReader(nullptr, "run.out"); }),
             "particlesim::OutputReader: no FILE to read run.out from (null)");
    const std::vector<Particle> start = two_disks();
    RunRecorder recorder(world, start, default_checkpoints);
    const std::vector<Particle> three(3);
    CHECK_EQ(refusal([&] { recorder.observe(1, three, {}); }),
             "particlesim::RunRecorder: observed 3 particles, but the run started with 2");
    CHECK_EQ(refusal([&] { recorder.observe(1, start, {}); }), "");
    CHECK_EQ(recorder.record().steps, std::int64_t{1});
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_options",
                      {{"stepped options are checked", stepped_options_are_checked},
                       {"exact options are checked", exact_options_are_checked},
                       {"bad worlds are refused by both engines", bad_worlds_are_refused_by_both_engines},
                       {"step check options are checked", step_check_options_are_checked},
                       {"null files and mismatched runs are refused", null_files_and_mismatched_runs_are_refused}});
}
