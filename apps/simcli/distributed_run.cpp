#include "distributed_run.hpp"

#include "checkpoint.hpp"
#include "cli_options.hpp"
#include "common/library_message.hpp"
#include "failure_words.hpp"
#include "first_part.hpp"
#include "interruptible_output.hpp"
#include "interrupts.hpp"
#include "mpi_launch.hpp"
#include "output_file.hpp"
#include "progress_line.hpp"
#include "run_stats.hpp"
#include "scene_input.hpp"

#include "particlesim/accuracy.hpp"
#include "particlesim/distributed_simulation.hpp"
#include "particlesim/state_writer.hpp"

#include <mpi.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace simcli {

namespace {

using namespace particlesim;

constexpr int root = 0;
constexpr int exit_failure = 1;
constexpr int exit_bad_input = 2;

// A failure on some rank, agreed by all: the worst exit status any rank
// reached, and the lowest rank that reached it, which prints its message.
class Agreement {
public:
    explicit Agreement(MPI_Comm comm) : comm_(comm) { MPI_Comm_rank(comm, &rank_); }

    // Collective: the worst status of all ranks (0: every rank went on).
    // The rank whose failure it is prints `message`; returns the status.
    int agree(int status, const std::string& message) const {
        struct {
            int status;
            int rank;
        } mine{status, rank_}, worst{};
        MPI_Allreduce(&mine, &worst, 1, MPI_2INT, MPI_MAXLOC, comm_);
        if (worst.status != 0 && worst.rank == rank_) std::fprintf(stderr, "simcli: %s\n", message.c_str());
        return worst.status;
    }

private:
    MPI_Comm comm_;
    int rank_ = 0;
};

// Thrown once a collective agreed to stop: the status every rank exits with.
struct Stop {
    int status;
};

// A failure only this rank has, in the middle of a collective step: nothing
// can be agreed any more, so the whole run is stopped.
[[noreturn]] void abort_run(MPI_Comm comm, int rank, const std::exception& failure) {
    std::fprintf(stderr, "simcli: rank %d: %s; stopping every rank\n", rank, failure_words(failure).c_str());
    std::fflush(stderr);
    MPI_Abort(comm, exit_failure);
    std::abort();
}

// What only one process can do in a run of several ranks.
void refuse_on_ranks(const CliOptions& options, int ranks) {
    const std::string under =
        " runs on one process; under mpirun use -np 1 (this run has " + std::to_string(ranks) + " ranks)";
    if (options.engine == EngineChoice::exact) throw BadInput("--engine exact" + under);
    if (options.animation) throw BadInput("--animate" + under);
    if (options.snapshot_path) throw BadInput("--snapshot" + under);
    if (options.trajectory_path) throw BadInput("--trajectory" + under);
    if (options.observables_path) throw BadInput("--observables" + under);
}

// Rank 0's output of the states. A write that fails is kept, not thrown,
// so that every rank still takes part in the gather; the failure is agreed
// after it.
//
// Standard output under an MPI launcher is a pipe or terminal to the
// launcher, which stops reading it once it is signalled (mpirun signals its
// ranks a second later and kills them a second after that). There a signal
// ends the output where it stands (interruptible_output.hpp), so that the
// checkpoint and the message are not held up behind a write nobody reads.
class StateOutput {
public:
    StateOutput(const std::optional<std::string>& path, NumberFormat numbers)
        : file_(path),
          interruptible_(!path && forwarded_by_launcher() ? open_interruptible_standard_output() : nullptr),
          writer_(interruptible_ ? interruptible_.get() : file_.stream(), numbers),
          forwarded_(interruptible_ != nullptr) {
        if (forwarded_) let_interrupts_end_blocked_writes();
    }

    void write(std::int64_t step, std::size_t first, std::span<const Particle> part, bool final_block) {
        if (stopped()) return;
        try {
            if (final_block) {
                writer_.write_final(step, part, first);
            } else {
                writer_.write_state(step, part, first);
            }
        } catch (const OutputError& e) {
            fail(e);
        }
    }
    void flush() {
        if (stopped()) return;
        try {
            writer_.flush();
        } catch (const OutputError& e) {
            fail(e);
        }
    }
    void commit() {
        flush();
        if (stopped()) return;
        try {
            file_.commit();
        } catch (const OutputError& e) {
            failure_ = e.what();
        }
    }
    // At a checkpoint at `step`: the output so far on disk, in place (OutputFile::keep_so_far).
    FirstPart keep_so_far(std::int64_t step) {
        FirstPart part;
        part.step = step;
        flush();
        if (stopped()) return part;
        try {
            record_kept_file(part, "output", file_.keep_so_far());
        } catch (const OutputError& e) {
            failure_ = e.what();
        }
        return part;
    }
    // On a signal: the launcher's stream is left where it stands, unflushed.
    void stop_at_signal() {
        if (forwarded_) ended_ = true;
    }
    [[nodiscard]] bool forwarded() const { return forwarded_; }
    [[nodiscard]] const std::string& failure() const { return failure_; }

private:
    [[nodiscard]] bool stopped() const { return ended_ || !failure_.empty(); }

    // A write that a signal ended is no failure of the output.
    void fail(const OutputError& e) {
        if (forwarded_ && interrupt_received()) {
            ended_ = true;
        } else {
            failure_ = e.what();
        }
    }

    static bool forwarded_by_launcher() {
        struct stat standard {};
        return started_by_mpi_launcher() && fstat(STDOUT_FILENO, &standard) == 0 && !S_ISREG(standard.st_mode);
    }

    OutputFile file_;
    InterruptibleOutput interruptible_;
    StateWriter writer_;
    bool forwarded_ = false;
    bool ended_ = false;
    std::string failure_;
};

class RankRun {
public:
    RankRun(MPI_Comm comm, const CliOptions& options) : comm_(comm), agreement_(comm), options_(options) {
        MPI_Comm_rank(comm, &rank_);
        MPI_Comm_size(comm, &ranks_);
    }

    // Agrees on `status` (with this rank's message); throws Stop unless all went on.
    void agree(int status, const std::string& message = {}) const {
        const int worst = agreement_.agree(status, message);
        if (worst != 0) throw Stop{worst};
    }

    int run() {
        catch_interrupts();
        // A checkpoint is first written when due or on a signal, perhaps hours in.
        if (options_.checkpoint_path) {
            int status = 0;
            std::string message;
            if (on_root()) {
                try {
                    require_can_create(*options_.checkpoint_path);
                } catch (const OutputError& e) {
                    status = exit_bad_input;
                    message = e.what();
                }
            }
            agree(status, message);
        }
        std::optional<DistributedSimulation> engine;
        RunSettings settings;
        if (options_.resume_path) {
            engine = resumed(settings);
        } else {
            engine = started(settings);
        }
        return write_run(*engine, settings);
    }

private:
    [[nodiscard]] bool on_root() const { return rank_ == root; }

    void broadcast_settings(RunSettings& settings) const {
        static_assert(std::is_trivially_copyable_v<RunSettings>);
        MPI_Bcast(&settings, sizeof(RunSettings), MPI_BYTE, root, comm_);
    }

    DistributedSimulation started(RunSettings& settings) const {
        LoadedScene loaded;
        int status = 0;
        std::string message;
        if (on_root()) {
            try {
                loaded = load_scene(options_);
                settings = {loaded.scene.world, loaded.scene.steps,        loaded.scene.mode, options_.engine,
                            options_.boundary,  options_.stepped.substeps, options_.numbers};
            } catch (const BadInput& e) {
                status = exit_bad_input;
                message = e.what();
            } catch (const std::exception& e) {  // cannot allocate the scene, ...
                status = exit_failure;
                message = e.what();
            }
        }
        agree(status, message);
        broadcast_settings(settings);
        return engine_or_stop([&] {
            return DistributedSimulation(comm_, settings.world, std::move(loaded.particles), options_.stepped);
        });
    }

    DistributedSimulation resumed(RunSettings& settings) const {
        const std::string& path = *options_.resume_path;
        Checkpoint checkpoint;
        int status = 0;
        std::string message;
        if (on_root()) {
            try {
                checkpoint = read_checkpoint(path);
                refuse_writing_over_first_part(checkpoint.first_part, {{"-o", options_.output_path}});
                settings = checkpoint.settings;
                if (settings.engine == EngineChoice::exact) {
                    CliOptions as_saved;
                    as_saved.engine = EngineChoice::exact;
                    refuse_on_ranks(as_saved, ranks_);
                }
            } catch (const std::invalid_argument& e) {
                status = exit_bad_input;
                message = e.what();
            } catch (const BadInput& e) {
                status = exit_bad_input;
                message = path + ": " + e.what();
            }
        }
        agree(status, message);
        broadcast_settings(settings);
        SteppedOptions stepped = options_.stepped;
        stepped.substeps = settings.substeps;
        DistributedSimulation engine = engine_or_stop([&] {
            return DistributedSimulation::restore(comm_, settings.world,
                                                  on_root() ? checkpoint.engine_state.get() : nullptr, stepped);
        });
        // The first part's files, as simcli in one process does (first_part.hpp).
        const FirstPart& first_part = checkpoint.first_part;
        if (on_root()) {
            try {
                require_first_part_at(first_part, engine.steps_done());
            } catch (const std::invalid_argument& e) {
                status = exit_bad_input;
                message = path + ": " + e.what();
            }
        }
        agree(status, message);
        if (on_root()) cut_back_first_part(first_part);
        return engine;
    }

    // The engine refuses alike on every rank (invalid_argument): rank 0 says why.
    template <typename Make>
    DistributedSimulation engine_or_stop(Make&& make) const {
        try {
            return make();
        } catch (const std::invalid_argument& e) {
            const std::string prefix = options_.resume_path ? *options_.resume_path + ": " : std::string();
            if (on_root())
                std::fprintf(stderr, "simcli: %s%s\n", prefix.c_str(),
                             apps_common::without_library_names(e.what()).c_str());
            throw Stop{exit_bad_input};
        }
    }

    // Every rank hands its particles over; rank 0 writes them, and sums their energy.
    double write_state(const DistributedSimulation& engine, std::optional<StateOutput>& output, std::int64_t step,
                       bool final_block) const {
        KineticEnergySum energy;
        engine.gather([&](std::size_t first, std::span<const Particle> part) {
            if (output) output->write(step, first, part, final_block);
            energy.add(part);
        });
        return energy.total();
    }

    double energy_of(const DistributedSimulation& engine) const {
        KineticEnergySum energy;
        engine.gather([&](std::size_t, std::span<const Particle> part) { energy.add(part); });
        return energy.total();
    }

    // The checkpoint, written by rank 0 as the parts arrive (never the whole
    // state at once). Returns rank 0's failure, if any.
    std::string write_checkpoint_file(const DistributedSimulation& engine, const RunSettings& settings,
                                      const FirstPart& first_part) const {
        std::optional<OutputFile> file;
        std::string failure;
        if (on_root()) {
            try {
                file.emplace(*options_.checkpoint_path);
                std::ostringstream header;
                write_settings(header, settings, first_part);
                file->write(header.str(), "checkpoint");
            } catch (const OutputError& e) {
                failure = e.what();
            }
        }
        engine.save([&](std::string_view text) {
            if (!failure.empty()) return;
            try {
                file->write(text, "checkpoint");
            } catch (const OutputError& e) {
                failure = e.what();
            }
        });
        if (on_root() && failure.empty()) {
            try {
                file->commit();
            } catch (const OutputError& e) {
                failure = e.what();
            }
        }
        return failure;
    }

    int write_run(DistributedSimulation& engine, const RunSettings& settings) const {
        RunStats stats;
        const std::int64_t first_step = engine.steps_done();
        stats.steps_run = settings.steps - first_step;
        std::optional<StateOutput> output;
        {
            int status = 0;
            std::string message;
            if (on_root()) {
                try {
                    output.emplace(options_.output_path, settings.numbers);
                } catch (const OutputError& e) {
                    status = exit_failure;
                    message = e.what();
                }
            }
            agree(status, message);
        }
        const auto failure_status = [&] { return output && !output->failure().empty() ? exit_failure : 0; };
        const auto failure_message = [&] { return output ? output->failure() : std::string(); };
        if (first_step == 0) {
            stats.initial_energy = write_state(engine, output, 0, false);
        } else if (options_.stats) {
            stats.initial_energy = energy_of(engine);
        }
        const bool print = settings.mode == OutputMode::print;
        const auto start = std::chrono::steady_clock::now();
        {
            std::optional<ProgressLine> progress;
            if (on_root()) progress.emplace(options_.progress, first_step, settings.steps, options_.progress_every);
            for (std::int64_t step = first_step; step < settings.steps;) {
                try {
                    engine.step();
                } catch (const std::exception& e) {
                    abort_run(comm_, rank_, e);
                }
                ++step;
                if (print && step < settings.steps) write_state(engine, output, step, false);
                if (progress) progress->update(step);
                // Any rank's signal stops every rank; so does a failed write.
                int signals[2] = {pending_interrupt(), failure_status()};
                MPI_Allreduce(MPI_IN_PLACE, signals, 2, MPI_INT, MPI_MAX, comm_);
                const int signal = signals[0];
                if (signals[1] != 0) agree(failure_status(), failure_message());
                const bool due = options_.checkpoint_every && step % *options_.checkpoint_every == 0;
                if (signal != 0 && output) output->stop_at_signal();
                if (options_.checkpoint_path && (signal != 0 || due)) {
                    FirstPart first_part;
                    first_part.step = step;
                    if (output) first_part = output->keep_so_far(step);
                    const std::string failure = write_checkpoint_file(engine, settings, first_part);
                    agree(failure.empty() ? failure_status() : exit_failure,
                          failure.empty() ? failure_message() : failure);
                }
                if (signal != 0) {
                    if (output) output->flush();
                    if (options_.checkpoint_path && output) output->commit();
                    agree(failure_status(), failure_message());
                    if (on_root()) {
                        const std::string message =
                            output->forwarded()
                                ? forwarded_output_interruption_message(step, settings.steps, options_.checkpoint_path)
                                : interruption_message(step, settings.steps, options_.checkpoint_path,
                                                       options_.output_path);
                        std::fprintf(stderr, "simcli: %s\n", message.c_str());
                    }
                    throw Stop{128 + signal};
                }
            }
        }
        stats.final_energy = write_state(engine, output, settings.steps, true);
        if (output) output->commit();
        agree(failure_status(), failure_message());
        stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats.totals = engine.totals();
        if (options_.stats && on_root()) {
            print_stats("step", stats, settings.steps);
            std::fprintf(stderr, "stats: pair search %s\n", pair_search_name(engine.pair_search()));
            std::fprintf(stderr, "stats: threads %d, ranks %d\n", engine.threads(), ranks_);
        }
        return 0;
    }

    MPI_Comm comm_;
    Agreement agreement_;
    const CliOptions& options_;
    int rank_ = 0;
    int ranks_ = 1;
};

int run_ranks(int argc, char** argv, MPI_Comm comm) {
    int rank = 0, ranks = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &ranks);
    // Only rank 0 writes to stdout (the states, --help, --version).
    if (rank != root && std::freopen("/dev/null", "w", stdout) == nullptr) return exit_failure;
    std::optional<CliOptions> options;
    try {
        options = parse_arguments(argc, argv);
        if (options) refuse_on_ranks(*options, ranks);
    } catch (const BadInput& e) {
        // Every rank parsed the same arguments: all refuse, rank 0 says why.
        if (rank == root) std::fprintf(stderr, "simcli: %s\n", apps_common::without_library_names(e.what()).c_str());
        return exit_bad_input;
    }
    if (!options) return 0;
    try {
        return RankRun(comm, *options).run();
    } catch (const Stop& stop) {
        return stop.status;
    } catch (const std::exception& e) {  // this rank alone: it cannot allocate, ...
        abort_run(comm, rank, e);
    }
}

}  // namespace

int run_under_mpi(int argc, char** argv, int (*one_process)(int, char**)) {
#ifdef __GLIBC__
    // Buffers of a megabyte or more are mapped on their own and returned
    // whole when freed: without this, glibc's threshold rises after rank 0
    // frees the scene it read, and the run's buffers then come from a heap
    // that keeps every page it ever touched (docs/distributed.md, "Memory").
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
    int provided = 0;
    if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        std::fprintf(stderr, "simcli: MPI could not start\n");
        return exit_failure;
    }
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    const int status = ranks == 1 ? one_process(argc, argv) : run_ranks(argc, argv, MPI_COMM_WORLD);
    std::fflush(stdout);
    MPI_Finalize();
    return status;
}

}  // namespace simcli
