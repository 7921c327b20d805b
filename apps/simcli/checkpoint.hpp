#pragma once
// A checkpoint: the run's settings (the world, the steps, the output mode,
// the engine and what changes its results) followed by the engine's exact
// state (SteppedSimulation::save / ExactSimulation::save). Written atomically,
// so an interrupted write leaves the previous checkpoint intact.

#include "particlesim/scene.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/world.hpp"

#include <cstdint>
#include <istream>
#include <memory>
#include <string>

namespace simcli {

enum class EngineChoice { step, exact };

// Everything about a run that its output depends on, besides the particles.
struct RunSettings {
    particlesim::World world;
    std::int64_t steps = 0;
    particlesim::OutputMode mode = particlesim::OutputMode::perf;
    EngineChoice engine = EngineChoice::step;
    particlesim::Boundary boundary = particlesim::Boundary::walls;  // periodic: the exact engine only
    int substeps = 1;
    particlesim::NumberFormat numbers = particlesim::NumberFormat::fixed8;
};

// Writes settings and `save_engine(stream)` to `path`. Throws particlesim::OutputError.
template <typename SaveEngine>
void write_checkpoint(const std::string& path, const RunSettings& settings, SaveEngine&& save_engine);

// A checkpoint read back: its settings, and a stream at the engine's state.
struct Checkpoint {
    RunSettings settings;
    std::unique_ptr<std::istream> engine_state;
};

// Throws std::invalid_argument naming the file and what is wrong.
Checkpoint read_checkpoint(const std::string& path);

// The settings' part of a checkpoint (used by write_checkpoint).
void write_settings(std::ostream& out, const RunSettings& settings);

}  // namespace simcli

#include "output_file.hpp"

#include <ostream>
#include <sstream>

template <typename SaveEngine>
void simcli::write_checkpoint(const std::string& path, const RunSettings& settings, SaveEngine&& save_engine) {
    std::ostringstream text;
    write_settings(text, settings);
    save_engine(text);
    OutputFile file(path);
    file.write(text.str(), "checkpoint");
    file.commit();
}
