// simcli: reads a scene, runs it, writes the states (io.md). Thin by design:
// arguments -> scene -> simulation -> output; the library does the work.

#include "particlesim/particlesim.hpp"

#include <getopt.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace {

using namespace particlesim;

constexpr int exit_failure = 1;
constexpr int exit_bad_input = 2;
constexpr std::uint64_t max_substeps = 1u << 20;

constexpr const char* usage_text =
    R"(usage: simcli [OPTIONS] [SCENE]           SCENE: a scene file; '-' or absent: stdin

Simulates N hard disks bouncing elastically in a square box, in discrete steps.

  -o, --output FILE                write the output to FILE instead of stdout
  -t, --threads N                  worker threads (default: OpenMP's default)
      --seed N                     seed of a random scene (default 3210)
      --broadphase auto|brute|grid pair search (default auto); all give identical output
      --grid G                     the grid search with a G x G grid (1 <= G <= 4096;
                                   4 = the 4 x 4 grid of L/4 cells); not with --broadphase brute
      --substeps K                 K micro-steps per step (default 1)
      --engine step|exact          exact = continuous-time event-driven engine
                                   (one thread; needs a start without overlaps)
      --stats                      a summary on stderr after the run: steps per
                                   second, collisions, energy drift, pair tests
  -h, --help                       this text, exit 0
      --version                    the version, exit 0

Exit status: 0 success, 1 failure while running (output not writable),
2 bad usage or bad input.
)";

// Bad usage or bad input: one line on stderr, exit 2.
class BadInput : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class EngineChoice { step, exact };

struct CliOptions {
    std::string scene_path = "-";
    std::optional<std::string> output_path;
    EngineChoice engine = EngineChoice::step;
    bool stats = false;
    bool step_engine_options = false;       // --broadphase, --grid or --substeps given
    std::optional<PairSearch> pair_search;  // --broadphase
    SteppedOptions stepped;
    RandomSceneOptions random;
};

// Beyond this many estimated events the exact engine would run for hours (or
// forever: a disk that fills the box, speeds far above the box per step).
constexpr double exact_event_limit = 2e9;

std::uint64_t parse_unsigned(std::string_view option, std::string_view text, std::uint64_t min, std::uint64_t max) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size() || value < min || value > max) {
        throw BadInput(std::string(option) + ": expected an integer in [" + std::to_string(min) + ", " +
                       std::to_string(max) + "], found \"" + std::string(text) + "\"");
    }
    return value;
}

enum LongOnly { opt_seed = 256, opt_broadphase, opt_grid, opt_substeps, opt_engine, opt_stats, opt_version };

// Returns nothing when --help or --version has been answered.
std::optional<CliOptions> parse_arguments(int argc, char** argv) {
    static const option long_options[] = {{"output", required_argument, nullptr, 'o'},
                                          {"threads", required_argument, nullptr, 't'},
                                          {"seed", required_argument, nullptr, opt_seed},
                                          {"broadphase", required_argument, nullptr, opt_broadphase},
                                          {"grid", required_argument, nullptr, opt_grid},
                                          {"substeps", required_argument, nullptr, opt_substeps},
                                          {"engine", required_argument, nullptr, opt_engine},
                                          {"stats", no_argument, nullptr, opt_stats},
                                          {"help", no_argument, nullptr, 'h'},
                                          {"version", no_argument, nullptr, opt_version},
                                          {nullptr, 0, nullptr, 0}};
    CliOptions options;
    opterr = 0;  // our own one-line messages
    for (int c; (c = getopt_long(argc, argv, ":o:t:h", long_options, nullptr)) != -1;) {
        const std::string_view value = optarg != nullptr ? optarg : "";
        switch (c) {
        case 'o': options.output_path = std::string(value); break;
        case 't': options.stepped.threads = static_cast<int>(parse_unsigned("--threads", value, 1, 1024)); break;
        case opt_seed: options.random.seed = parse_unsigned("--seed", value, 0, UINT64_MAX); break;
        case opt_broadphase:
            options.step_engine_options = true;
            if (value == "auto") {
                options.pair_search = PairSearch::automatic;
            } else if (value == "brute") {
                options.pair_search = PairSearch::brute_force;
            } else if (value == "grid") {
                options.pair_search = PairSearch::grid;
            } else {
                throw BadInput("--broadphase: expected auto, brute or grid, found \"" + std::string(value) + "\"");
            }
            break;
        case opt_grid:
            options.step_engine_options = true;
            options.stepped.grid_cells = static_cast<int>(parse_unsigned("--grid", value, 1, max_grid_cells));
            break;
        case opt_substeps:
            options.step_engine_options = true;
            options.stepped.substeps = static_cast<int>(parse_unsigned("--substeps", value, 1, max_substeps));
            break;
        case opt_engine:
            if (value == "step") {
                options.engine = EngineChoice::step;
            } else if (value == "exact") {
                options.engine = EngineChoice::exact;
            } else {
                throw BadInput("--engine: expected step or exact, found \"" + std::string(value) + "\"");
            }
            break;
        case opt_stats: options.stats = true; break;
        case 'h': std::fputs(usage_text, stdout); return std::nullopt;
        case opt_version: std::printf("simcli %s\n", particlesim::version); return std::nullopt;
        case ':': throw BadInput(std::string("option ") + argv[optind - 1] + " needs a value (see simcli --help)");
        default: throw BadInput(std::string("unknown option ") + argv[optind - 1] + " (see simcli --help)");
        }
    }
    if (argc - optind > 1)
        throw BadInput("expected at most one scene file, found " + std::to_string(argc - optind) +
                       " (see simcli --help)");
    if (argc - optind == 1) options.scene_path = argv[optind];
    if (options.engine == EngineChoice::exact && options.step_engine_options) {
        throw BadInput("--broadphase, --grid and --substeps belong to the step engine, not to --engine exact");
    }
    // --grid G is a grid search with a G x G grid; it contradicts only --broadphase brute.
    if (options.stepped.grid_cells && options.pair_search == PairSearch::brute_force) {
        throw BadInput("--grid G is the grid search, not with --broadphase brute");
    }
    options.stepped.pair_search =
        options.stepped.grid_cells ? PairSearch::grid : options.pair_search.value_or(PairSearch::automatic);
    return options;
}

Scene read_input(const std::string& path, const std::string& name, SceneLines& lines) {
    if (path == "-") return read_scene(std::cin, &lines);
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw BadInput(name + ": is a directory");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw BadInput(name + ": cannot open: " + std::strerror(errno));
    return read_scene(file, &lines);
}

// Writes the run of `engine` (either engine) and returns its run time in seconds.
template <Engine E>
double write_run(std::FILE* out, E& engine, const Scene& scene) {
    StateWriter writer(out);
    writer.write_state(0, engine.particles());
    const auto start = std::chrono::steady_clock::now();
    if (scene.mode == OutputMode::print) {
        run(engine, scene.steps, [&](std::int64_t step, std::span<const Particle> particles) {
            if (step < scene.steps) writer.write_state(step, particles);
        });
    } else {
        run(engine, scene.steps);
    }
    writer.write_final(scene.steps, engine.particles());
    writer.flush();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct RunStats {
    double seconds = 0.0;
    StepCounts totals;
    double initial_energy = 0.0;
    double final_energy = 0.0;
};

void print_stats(const char* engine, const RunStats& stats, std::int64_t steps) {
    const double per_step = steps > 0 ? 1.0 / static_cast<double>(steps) : 0.0;
    std::fprintf(stderr, "stats: engine %s, %lld steps in %.6f s (%.6g steps/s)\n", engine,
                 static_cast<long long>(steps), stats.seconds,
                 stats.seconds > 0.0 ? static_cast<double>(steps) / stats.seconds : 0.0);
    std::fprintf(stderr, "stats: %llu particle collisions, %llu wall collisions\n",
                 static_cast<unsigned long long>(stats.totals.particle_collisions),
                 static_cast<unsigned long long>(stats.totals.wall_collisions));
    std::fprintf(stderr, "stats: relative energy drift %+.16e\n",
                 relative_energy_drift(stats.initial_energy, stats.final_energy));
    std::fprintf(stderr, "stats: %.6g candidate pairs tested per step\n",
                 static_cast<double>(stats.totals.pair_tests) * per_step);
}

// Runs the scene with `engine` into `output_path` (stdout when absent).
template <Engine E>
RunStats run_to_output(E& engine, const Scene& scene, const std::optional<std::string>& output_path) {
    RunStats stats;
    stats.initial_energy = total_kinetic_energy(engine.particles());
    if (!output_path) {
        stats.seconds = write_run(stdout, engine, scene);
    } else {
        std::FILE* out = std::fopen(output_path->c_str(), "wb");
        if (out == nullptr) throw OutputError(*output_path + ": cannot open for writing: " + std::strerror(errno));
        try {
            stats.seconds = write_run(out, engine, scene);
        } catch (...) {
            std::fclose(out);
            throw;
        }
        if (std::fclose(out) != 0) throw OutputError(*output_path + ": cannot write: " + std::strerror(errno));
    }
    stats.totals = engine.totals();
    stats.final_energy = total_kinetic_energy(engine.particles());
    return stats;
}

ExactSimulation make_exact_engine(const Scene& scene, std::vector<Particle> particles, const std::string& name) {
    const double events = estimated_events_per_step(scene.world, particles) * static_cast<double>(scene.steps);
    if (!(events <= exact_event_limit)) {
        char message[200];
        std::snprintf(message, sizeof message,
                      "the exact engine would need about %.3g events for this scene (limit %.3g); "
                      "use fewer steps or the step engine",
                      events, exact_event_limit);
        throw BadInput(name + ": " + message);
    }
    try {
        return ExactSimulation(scene.world, std::move(particles));
    } catch (const OverlappingStart& e) {
        throw BadInput(name + ": " + e.what());
    }
}

int run_cli(int argc, char** argv) {
    const std::optional<CliOptions> options = parse_arguments(argc, argv);
    if (!options) return 0;
    const std::string name = options->scene_path == "-" ? "<stdin>" : options->scene_path;

    Scene scene;
    SceneLines lines;
    std::vector<Particle> particles;
    try {
        scene = read_input(options->scene_path, name, lines);
        particles = scene.is_random() ? make_random_particles(scene.particle_count, scene.world, options->random)
                                      : std::move(scene.particles);
    } catch (const InputError& e) {
        throw BadInput(name + ":" + std::to_string(e.line()) + ": " + e.what());
    } catch (const SceneTooFull& e) {
        throw BadInput(name + ":" + std::to_string(lines.particle_count) + ": " + e.what());
    }

    if (options->engine == EngineChoice::exact) {
        ExactSimulation engine = make_exact_engine(scene, std::move(particles), name);
        const RunStats stats = run_to_output(engine, scene, options->output_path);
        if (options->stats) print_stats("exact", stats, scene.steps);
    } else {
        SteppedSimulation engine(scene.world, std::move(particles), options->stepped);
        const RunStats stats = run_to_output(engine, scene, options->output_path);
        if (options->stats) print_stats("step", stats, scene.steps);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGPIPE, SIG_IGN);  // a closed pipe is a write error (exit 1), not a signal
    try {
        return run_cli(argc, argv);
    } catch (const BadInput& e) {
        std::fprintf(stderr, "simcli: %s\n", e.what());
        return exit_bad_input;
    } catch (const std::exception& e) {  // OutputError and any other failure while running
        std::fprintf(stderr, "simcli: %s\n", e.what());
        return exit_failure;
    }
}
