// simcli: reads a scene (or a checkpoint), runs it, writes the states (io.md).
// Thin by design: arguments -> scene -> engine -> output; the library does
// the work. The pieces around the run live beside this file: the command
// line, the output file, checkpoints, interrupts and the progress line.

#include "animation.hpp"
#include "checkpoint.hpp"
#include "cli_options.hpp"
#include "common/library_message.hpp"
#include "common/standard_streams.hpp"
#include "distributed_run.hpp"
#include "failure_words.hpp"
#include "first_part.hpp"
#include "interrupts.hpp"
#include "mpi_launch.hpp"
#include "observables_file.hpp"
#include "output_file.hpp"
#include "progress_line.hpp"
#include "run_stats.hpp"
#include "scene_input.hpp"
#include "snapshot.hpp"
#include "trajectory.hpp"

#include "particlesim/particlesim.hpp"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace {

using namespace particlesim;
using namespace simcli;

constexpr int exit_failure = 1;
constexpr int exit_bad_input = 2;

// A run stopped by SIGINT, SIGTERM or SIGHUP, after a clean flush: exit 128 + signal.
class Interrupted : public std::runtime_error {
public:
    Interrupted(int signal, const std::string& message) : std::runtime_error(message), signal_(signal) {}
    [[nodiscard]] int signal() const { return signal_; }

private:
    int signal_;
};

// What --animate, --snapshot, --trajectory and --observables collect while the run goes on.
struct Pictures {
    std::optional<Animation> animation;
    std::optional<std::string> snapshot_path;
    std::int64_t snapshot_step = 0;
    std::optional<Trajectory> trajectory;
    std::optional<ObservablesFile> observables;  // the exact engine's
    ColourBy colour_by = ColourBy::speed;        // the snapshot's (the page keeps its own)
    Boundary boundary = Boundary::walls;
    std::optional<OpenRow> resumed_row;  // a checkpoint's open observables row, which the run goes on with

    // --trajectory and --observables opened, and --checkpoint tried, before
    // anything runs: a file that cannot be written is bad input.
    void open_files(const CliOptions& options, const World& world, Boundary box_boundary, std::int64_t steps) {
        // The picture is written at its step, perhaps the last: tried now, and
        // refused as --animate's page is (a failure to write, exit 1).
        if (options.snapshot_path) require_can_create(*options.snapshot_path);
        try {
            if (options.trajectory_path) {
                trajectory.emplace(*options.trajectory_path, world, box_boundary, options.trajectory_every, steps);
            }
            if (options.observables_path) {
                observables.emplace(*options.observables_path, world, box_boundary, options.observe_every, steps,
                                    options.measure_from);
            }
            // A checkpoint is first written when due or on a signal, perhaps hours in.
            if (options.checkpoint_path) require_can_create(*options.checkpoint_path);
        } catch (const OutputError& e) {
            throw BadInput(e.what());
        }
    }

    // The run's first step: 0, whose state a whole run pictures, or a
    // checkpoint's (a resumed run writes only what comes after it). The
    // observables' first interval begins here, or where the checkpoint's
    // open row began.
    template <Engine E>
    void start(std::int64_t step, const E& engine, const World& world) {
        if (step == 0) picture_state(0, engine, world);
        if constexpr (requires { engine.collision_sums(); }) {
            if (observables && resumed_row) {
                observables->start(resumed_row->step, resumed_row->totals, resumed_row->sums);
            } else if (observables) {
                observables->start(step, engine.totals(), engine.collision_sums());
            }
        }
    }

    // Every step after the first.
    template <Engine E>
    void observe(std::int64_t step, const E& engine, const World& world) {
        picture_state(step, engine, world);
        if constexpr (requires { engine.collision_sums(); }) {
            if (observables) observables->observe(step, engine.particles(), engine.totals(), engine.collision_sums());
        }
    }

    // A run stopped at `step` with a checkpoint: the observables end with a
    // row up to `step`, so that a resumed run's rows go on from there.
    template <Engine E>
    void close_rows_at(std::int64_t step, const E& engine) {
        if constexpr (requires { engine.collision_sums(); }) {
            if (observables) observables->end_at(step, engine.particles(), engine.totals(), engine.collision_sums());
        }
    }

    // At a checkpoint at `step`: the output, the trajectory and the
    // observables so far on disk and in place, and where each ends.
    FirstPart keep_so_far(std::int64_t step, OutputFile& output) {
        FirstPart part;
        part.step = step;
        record_kept_file(part, "output", output.keep_so_far());
        if (trajectory) record_kept_file(part, "trajectory", trajectory->keep_so_far());
        if (observables) {
            record_kept_file(part, "observables", observables->keep_so_far());
            part.observables_row =
                OpenRow{observables->open_row_step(), observables->open_row_totals(), observables->open_row_sums()};
        }
        return part;
    }

    void commit() {
        if (trajectory) trajectory->commit();
        if (observables) observables->commit();
    }

private:
    template <Engine E>
    void picture_state(std::int64_t step, const E& engine, const World& world) {
        if (animation && animation->per_step() == 1 && animation->wants(step)) {
            if constexpr (requires { engine.collision_sums(); }) {
                animation->add_frame(static_cast<double>(step), engine.particles(), engine.totals(), 1.0,
                                     &engine.collision_sums());
            } else {
                animation->add_frame(static_cast<double>(step), engine.particles(), engine.totals());
            }
        }
        if (snapshot_path && step == snapshot_step) {
            write_snapshot(*snapshot_path, world, engine.particles(), step, colour_by, boundary);
        }
        if (trajectory) trajectory->observe(step, engine.particles());
    }
};

// The files an interrupted run names beside its output: the trajectory and the observables.
std::vector<std::string> side_files(const CliOptions& options) {
    std::vector<std::string> files;
    if (options.observables_path) files.push_back(*options.observables_path);
    if (options.trajectory_path) files.push_back(*options.trajectory_path);
    return files;
}

// Runs `engine` from its current step to settings.steps, writing the states.
template <Engine E>
RunStats write_run(E& engine, const RunSettings& settings, const CliOptions& options, Pictures& pictures) {
    RunStats stats;
    stats.initial_energy = total_kinetic_energy(engine.particles());
    const std::int64_t first_step = engine.steps_done();
    stats.steps_run = settings.steps - first_step;
    OutputFile output(options.output_path);
    StateWriter writer(output.stream(), settings.numbers);
    if (settings.boundary == Boundary::periodic) writer.wrap_positions_into(settings.world.box_size);
    // A resumed run goes on where the first part of its output ends.
    if (first_step == 0) writer.write_state(0, engine.particles());
    pictures.start(first_step, engine, settings.world);
    const bool print = settings.mode == OutputMode::print;
    const auto start = std::chrono::steady_clock::now();
    {
        ProgressLine progress(options.progress, first_step, settings.steps, options.progress_every);
        for (std::int64_t step = first_step; step < settings.steps;) {
            engine.step();
            ++step;
            if (print && step < settings.steps) writer.write_state(step, engine.particles());
            pictures.observe(step, engine, settings.world);
            progress.update(step);
            const int signal = pending_interrupt();
            const bool due = options.checkpoint_every && step % *options.checkpoint_every == 0;
            if (options.checkpoint_path && (signal != 0 || due)) {
                if (signal != 0) pictures.close_rows_at(step, engine);
                writer.flush();  // the output holds every block up to `step`, the checkpoint goes on from there
                const FirstPart first_part = pictures.keep_so_far(step, output);
                write_checkpoint(*options.checkpoint_path, settings, first_part,
                                 [&](std::ostream& out) { engine.save(out); });
            }
            if (signal != 0) {
                writer.flush();  // whole blocks only: what stdout shows ends at a step
                // With a checkpoint, the output is the first part of the run; --resume writes the rest.
                if (options.checkpoint_path) {
                    output.commit();
                    pictures.commit();
                }
                throw Interrupted(signal, interruption_message(step, settings.steps, options.checkpoint_path,
                                                               options.output_path, side_files(options)));
            }
        }
    }
    writer.write_final(settings.steps, engine.particles());
    writer.flush();
    output.commit();
    pictures.commit();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.totals = engine.totals();
    stats.final_energy = total_kinetic_energy(engine.particles());
    return stats;
}

// The pressure with its error bar from block averages of the observables'
// rows; with 16 blocks, the virial's error from 8 blocks twice as long too.
void print_pressure(const ObservablesFile& observables) {
    const MeanWithError virial = observables.virial_pressure(), walls = observables.wall_pressure();
    if (virial.blocks == 0) {
        std::fprintf(stderr, "stats: pressure: fewer than four observables rows from step %lld\n",
                     static_cast<long long>(observables.measure_from()));
        return;
    }
    char longer[64] = "";
    if (virial.blocks == 16) {
        std::snprintf(longer, sizeof longer, " (8 longer blocks: +- %.2g)", observables.virial_pressure(8).error);
    }
    if (observables.periodic()) {
        std::fprintf(stderr,
                     "stats: pressure beta P (2r)^2 = %.6g +- %.2g (virial, periodic box); %zu blocks of the "
                     "observables rows from step %lld%s\n",
                     virial.mean, virial.error, virial.blocks, static_cast<long long>(observables.measure_from()),
                     longer);
        return;
    }
    std::fprintf(stderr,
                 "stats: pressure beta P (2r)^2 = %.6g +- %.2g (virial), %.6g +- %.2g (walls); %zu blocks of the "
                 "observables rows from step %lld%s\n",
                 virial.mean, virial.error, walls.mean, walls.error, virial.blocks,
                 static_cast<long long>(observables.measure_from()), longer);
}

template <Engine E>
void run_and_report(E& engine, const RunSettings& settings, const CliOptions& options, Pictures& pictures) {
    RunStats stats;
    try {
        stats = write_run(engine, settings, options, pictures);
    } catch (const Interrupted&) {
        // The rows kept (with a checkpoint) still give their pressure.
        if (options.stats && options.checkpoint_path && pictures.observables) print_pressure(*pictures.observables);
        throw;
    }
    if (!options.stats) return;
    print_stats(settings.engine == EngineChoice::exact ? "exact" : "step", stats, settings.steps);
    if (pictures.observables) print_pressure(*pictures.observables);
    if constexpr (std::is_same_v<E, ExactSimulation>) {
        const auto events = static_cast<double>(engine.events_processed());
        std::fprintf(stderr,
                     "stats: %.0f events (collisions, cell crossings, stale pair predictions), %.6g per second\n",
                     events, stats.seconds > 0.0 ? events / stats.seconds : 0.0);
        const int side = engine.cells_per_side();
        std::fprintf(stderr, "stats: neighbours by %s\n",
                     side == 1 ? "the particles' lines (one cell)"
                               : (std::to_string(side) + " x " + std::to_string(side) + " cells").c_str());
    } else {
        std::fprintf(stderr, "stats: pair search %s\n", particlesim::pair_search_name(engine.pair_search()));
        if (engine.threads() > 1 && engine.steps_on_one_thread() > 0) {
            std::fprintf(stderr, "stats: threads %d, one thread in %lld of %lld steps (timed trials)\n",
                         engine.threads(), static_cast<long long>(engine.steps_on_one_thread()),
                         static_cast<long long>(stats.steps_run));
        } else {
            std::fprintf(stderr, "stats: threads %d\n", engine.threads());
        }
    }
}

// Frames between whole steps (--engine exact --animate-every 1/k): continuous
// time has a state at every instant. A second run with every velocity divided
// by k takes k of its steps for one of the real run, so its states at whole
// steps are the real run's at multiples of 1/k (up to rounding).
void record_between_steps(Animation& animation, const World& world, std::vector<Particle> start, std::int64_t steps) {
    const int k = animation.per_step();
    const double slowed = 1.0 / k;
    for (Particle& p : start) p.velocity *= slowed;
    ExactSimulation sampler(world, std::move(start));
    animation.add_frame(0.0, sampler.particles(), sampler.totals(), slowed);
    for (std::int64_t j = 1; j <= steps * k; ++j) {
        sampler.step();
        animation.add_frame(static_cast<double>(j) * slowed, sampler.particles(), sampler.totals(), slowed);
    }
}

ExactSimulation make_exact_engine(const Scene& scene, std::vector<Particle> particles, const std::string& name,
                                  const SceneLines& lines, Boundary boundary) {
    try {
        require_feasible_exact_run(scene.world, particles, scene.steps);
    } catch (const std::invalid_argument& e) {
        throw BadInput(at_line(name, lines.steps) + e.what());
    }
    try {
        ExactOptions exact;
        exact.boundary = boundary;
        return ExactSimulation(scene.world, std::move(particles), exact);
    } catch (const OverlappingStart& e) {
        const long line = lines.particles.empty() ? lines.particle_count : lines.particles[e.first()];
        throw BadInput(at_line(name, line) + e.what());
    } catch (const std::invalid_argument& e) {  // a periodic box too small for its cells
        throw BadInput(at_line(name, lines.box_size) + e.what());
    }
}

void run_scene(const CliOptions& options) {
    LoadedScene loaded = load_scene(options);
    const std::string& name = loaded.name;
    const Scene& scene = loaded.scene;
    SceneLines& lines = loaded.lines;
    std::vector<Particle>& particles = loaded.particles;
    const RunSettings settings{scene.world,    scene.steps,      scene.mode,
                               options.engine, options.boundary, options.stepped.substeps,
                               options.numbers};
    Pictures pictures;
    pictures.colour_by = options.colour_by;
    pictures.boundary = options.boundary;
    if (options.snapshot_path) {
        pictures.snapshot_path = options.snapshot_path;
        pictures.snapshot_step = options.snapshot_step.value_or(scene.steps);
        if (pictures.snapshot_step > scene.steps) {
            throw BadInput(at_line(name, lines.steps) + "--snapshot-step " + std::to_string(pictures.snapshot_step) +
                           " is beyond the scene's S = " + std::to_string(scene.steps) + " steps");
        }
    }
    if (options.observables_path && options.measure_from > scene.steps) {
        throw BadInput(at_line(name, lines.steps) + "--measure-from " + std::to_string(options.measure_from) +
                       " is beyond the scene's S = " + std::to_string(scene.steps) + " steps");
    }
    // Caught before any file is made: a signal while the run starts (the
    // engine made, step 0 written) is seen after the first step, and never
    // leaves a temporary file behind.
    catch_interrupts();
    pictures.open_files(options, scene.world, options.boundary, scene.steps);
    const bool exact = options.engine == EngineChoice::exact;
    if (options.animation) {
        pictures.animation.emplace(*options.animation, scene.world, particles.size(), scene.steps,
                                   exact ? "exact" : "step", options.stepped.substeps, options.colour_by,
                                   options.boundary);
    }
    const bool between_steps = pictures.animation && pictures.animation->per_step() > 1;
    const std::vector<Particle> start = between_steps ? particles : std::vector<Particle>{};
    if (exact) {
        ExactSimulation engine = make_exact_engine(scene, std::move(particles), name, lines, options.boundary);
        lines = {};  // the particles' lines were kept for the messages above only
        run_and_report(engine, settings, options, pictures);
    } else {
        lines = {};
        SteppedSimulation engine(scene.world, std::move(particles), options.stepped);
        run_and_report(engine, settings, options, pictures);
    }
    if (between_steps) record_between_steps(*pictures.animation, scene.world, start, scene.steps);
    if (pictures.animation) pictures.animation->write();
}

void resume_run(const CliOptions& options) {
    const std::string& path = *options.resume_path;
    Checkpoint checkpoint;
    try {
        checkpoint = read_checkpoint(path);
        refuse_writing_over_first_part(checkpoint.first_part, {{"-o", options.output_path},
                                                               {"--trajectory", options.trajectory_path},
                                                               {"--observables", options.observables_path}});
    } catch (const std::invalid_argument& e) {
        throw BadInput(e.what());
    }
    const RunSettings& settings = checkpoint.settings;
    if (options.observables_path && settings.engine != EngineChoice::exact) {
        throw BadInput("--observables needs the exact engine; " + path + " is a checkpoint of the step engine");
    }
    if (options.observables_path && options.measure_from > settings.steps) {
        throw BadInput("--measure-from " + std::to_string(options.measure_from) + " is beyond the checkpointed run's " +
                       std::to_string(settings.steps) + " steps");
    }
    // The trajectory and the observables go on after the checkpoint's step
    // (--animate and --snapshot need the whole run).
    Pictures pictures;
    catch_interrupts();  // before any file is made, as for a scene
    pictures.open_files(options, settings.world, settings.boundary, settings.steps);
    try {
        if (settings.engine == EngineChoice::exact) {
            ExactOptions exact;
            exact.boundary = settings.boundary;
            ExactSimulation engine = ExactSimulation::restore(settings.world, *checkpoint.engine_state, exact);
            // As for a scene: the steps left must be within the engine's reach.
            require_feasible_exact_run(settings.world, engine.particles(), settings.steps - engine.steps_done());
            require_first_part_at(checkpoint.first_part, engine.steps_done());
            pictures.resumed_row = checkpoint.first_part.observables_row;
            cut_back_first_part(checkpoint.first_part);
            run_and_report(engine, settings, options, pictures);
        } else {
            SteppedOptions stepped = options.stepped;
            stepped.substeps = settings.substeps;
            SteppedSimulation engine = SteppedSimulation::restore(settings.world, *checkpoint.engine_state, stepped);
            require_first_part_at(checkpoint.first_part, engine.steps_done());
            cut_back_first_part(checkpoint.first_part);
            run_and_report(engine, settings, options, pictures);
        }
    } catch (const std::invalid_argument& e) {
        throw BadInput(path + ": " + e.what());
    }
}

int run_cli(int argc, char** argv) {
    const std::optional<CliOptions> options = parse_arguments(argc, argv);
    if (!options) return 0;
    if (options->resume_path) {
        resume_run(*options);
    } else {
        run_scene(*options);
    }
    return 0;
}

// simcli in one process: the exit status of io.md.
int run_one_process(int argc, char** argv) {
    try {
        return run_cli(argc, argv);
    } catch (const BadInput& e) {
        std::fprintf(stderr, "simcli: %s\n", apps_common::without_library_names(e.what()).c_str());
        return exit_bad_input;
    } catch (const Interrupted& e) {
        std::fprintf(stderr, "simcli: %s\n", apps_common::without_library_names(e.what()).c_str());
        return 128 + e.signal();
    } catch (const std::exception& e) {  // OutputError, TooManyEvents, out of memory, ... while running
        std::fprintf(stderr, "simcli: %s\n", failure_words(e).c_str());
        return exit_failure;
    }
}

}  // namespace

int main(int argc, char** argv) {
    // An output file must not take the number of a closed standard stream.
    if (!apps_common::open_closed_standard_streams()) return 2;
    std::signal(SIGPIPE, SIG_IGN);  // a closed pipe is a write error (exit 1), not a signal
#if defined(SIMCLI_WITH_MPI)
    // simcli-mpi: started otherwise, it never initialises MPI.
    if (simcli::started_by_mpi_launcher()) return run_under_mpi(argc, argv, run_one_process);
#elif defined(SIMCLI_DISTRIBUTED_SIBLING)
    if (simcli::started_by_mpi_launcher()) {
        simcli::become_sibling(SIMCLI_DISTRIBUTED_SIBLING, argv);
        return exit_failure;
    }
#else
    // Built without MPI: each rank would run the whole scene and write all of it.
    if (simcli::started_by_mpi_launcher() && simcli::launched_ranks() > 1) {
        if (simcli::first_launched_rank()) {
            std::fprintf(stderr,
                         "simcli: started on %ld ranks, but built without the distributed engine: run it in one "
                         "process, or build with -DPARTICLESIM_MPI=ON (docs/distributed.md)\n",
                         simcli::launched_ranks());
        }
        return exit_bad_input;
    }
#endif
    return run_one_process(argc, argv);
}
