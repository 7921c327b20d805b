#pragma once
// simcli's command line (io.md "simcli"): parsed and checked in one place,
// before anything is read or run.

#include "animation.hpp"
#include "checkpoint.hpp"
#include "colour_by.hpp"
#include "progress_line.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace simcli {

// Bad usage or bad input: one line on stderr, exit 2.
class BadInput : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct CliOptions {
    std::string scene_path = "-";
    std::optional<std::string> output_path;
    EngineChoice engine = EngineChoice::step;
    particlesim::Boundary boundary = particlesim::Boundary::walls;
    bool stats = false;
    particlesim::SteppedOptions stepped;  // searches and threads; substeps when not resuming
    particlesim::RandomSceneOptions random;
    particlesim::NumberFormat numbers = particlesim::NumberFormat::fixed8;
    std::optional<std::string> checkpoint_path;
    std::optional<std::int64_t> checkpoint_every;
    std::optional<std::string> resume_path;
    ProgressChoice progress = ProgressChoice::automatic;
    std::optional<double> progress_every;  // seconds between lines; empty: the line's own pace
    std::optional<AnimationRequest> animation;
    std::optional<std::string> snapshot_path;
    std::optional<std::int64_t> snapshot_step;  // empty: the last step
    ColourBy colour_by = ColourBy::speed;       // --animate and --snapshot
    std::optional<std::string> trajectory_path;
    std::int64_t trajectory_every = 1;
    std::optional<std::string> observables_path;
    std::int64_t observe_every = 1;
    std::int64_t measure_from = 0;
};

// Nothing when --help or --version has been answered. Throws BadInput.
std::optional<CliOptions> parse_arguments(int argc, char** argv);

}  // namespace simcli
