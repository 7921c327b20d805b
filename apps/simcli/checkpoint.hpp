#pragma once
// A checkpoint: the run's settings (the world, the steps, the output mode,
// the engine and what changes its results) followed by the engine's exact
// state (SteppedSimulation::save / ExactSimulation::save). Written atomically,
// so an interrupted write leaves the previous checkpoint intact.
//
// Between the two, the run's first part as it stood at the checkpoint: where
// each file it writes ended, and where the observables' open row began. A
// run killed outright after the checkpoint has written on past it;
// --resume cuts those files back (first_part.hpp) and goes on with the
// open row, so the two parts join as the uninterrupted run's files.

#include "particlesim/engine.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/world.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

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

// One file of the first part at the checkpoint: which (an absolute path,
// its device and inode) and how long.
struct KeptFile {
    std::string kind;  // "output", "trajectory" or "observables"
    std::string path;
    std::uint64_t bytes = 0;
    std::uint64_t device = 0;
    std::uint64_t inode = 0;
};

// Where the observables' row open at the checkpoint began.
struct OpenRow {
    std::int64_t step = 0;
    particlesim::StepCounts totals;
    particlesim::CollisionSums sums;
};

// The longest path a first part records (a longer one is left out).
inline constexpr std::size_t longest_recorded_path = 4096;

struct FirstPart {
    bool recorded = false;  // false in a checkpoint of the first format
    std::int64_t step = 0;  // the checkpoint's
    std::vector<KeptFile> files;
    std::optional<OpenRow> observables_row;
};

// Writes settings, the first part and `save_engine(stream)` to `path`.
// Throws particlesim::OutputError.
template <typename SaveEngine>
void write_checkpoint(const std::string& path, const RunSettings& settings, const FirstPart& first_part,
                      SaveEngine&& save_engine);

// A checkpoint read back: its settings, its first part (no files from a
// checkpoint of the first format), and a stream at the engine's state.
struct Checkpoint {
    RunSettings settings;
    FirstPart first_part;
    std::unique_ptr<std::istream> engine_state;
};

// Throws std::invalid_argument naming the file and what is wrong.
Checkpoint read_checkpoint(const std::string& path);
// The same from a stream, `name` in the messages.
Checkpoint read_checkpoint(std::unique_ptr<std::istream> stream, const std::string& name);

// The settings' and the first part's lines of a checkpoint (used by write_checkpoint).
void write_settings(std::ostream& out, const RunSettings& settings, const FirstPart& first_part);

}  // namespace simcli

#include "output_file.hpp"

#include <ostream>
#include <sstream>

template <typename SaveEngine>
void simcli::write_checkpoint(const std::string& path, const RunSettings& settings, const FirstPart& first_part,
                              SaveEngine&& save_engine) {
    std::ostringstream text;
    write_settings(text, settings, first_part);
    save_engine(text);
    OutputFile file(path);
    file.write(text.str(), "checkpoint");
    file.commit();
}
