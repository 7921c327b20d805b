// simcli: reads a scene, runs it, writes the states (io.md). Thin by design:
// arguments -> scene -> simulation -> output; the library does the work.

#include "particlesim/grid_search.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/scene_reader.hpp"
#include "particlesim/simulation.hpp"
#include "particlesim/state_writer.hpp"
#include "particlesim/version.hpp"

#include <getopt.h>

#include <cerrno>
#include <charconv>
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

constexpr const char* usage_text =
    R"(usage: simcli [OPTIONS] [SCENE]           SCENE: a scene file; '-' or absent: stdin

Simulates N hard disks bouncing elastically in a square box, in discrete steps.

  -o, --output FILE                write the output to FILE instead of stdout
  -t, --threads N                  worker threads (default: OpenMP's default)
      --seed N                     seed of a random scene (default 3210)
      --broadphase auto|brute|grid candidate search (default auto); all give identical output
      --grid G                     force a G x G grid (4 = the 4 x 4 grid of L/4 cells)
      --substeps K                 K micro-steps per step (default 1)
      --engine step|exact          exact = continuous-time event-driven engine
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

struct CliOptions {
    std::string scene_path = "-";
    std::optional<std::string> output_path;
    SimOptions sim;
    RandomSceneOptions random;
};

std::uint64_t parse_unsigned(std::string_view option, std::string_view text, std::uint64_t min, std::uint64_t max) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size() || value < min || value > max) {
        throw BadInput(std::string(option) + ": expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                       "], found \"" + std::string(text) + "\"");
    }
    return value;
}

enum LongOnly { opt_seed = 256, opt_broadphase, opt_grid, opt_substeps, opt_engine, opt_version };

// Returns nothing when --help or --version has been answered.
std::optional<CliOptions> parse_arguments(int argc, char** argv) {
    static const option long_options[] = {
        {"output", required_argument, nullptr, 'o'},      {"threads", required_argument, nullptr, 't'},
        {"seed", required_argument, nullptr, opt_seed},   {"broadphase", required_argument, nullptr, opt_broadphase},
        {"grid", required_argument, nullptr, opt_grid},   {"substeps", required_argument, nullptr, opt_substeps},
        {"engine", required_argument, nullptr, opt_engine}, {"help", no_argument, nullptr, 'h'},
        {"version", no_argument, nullptr, opt_version},   {nullptr, 0, nullptr, 0}};
    CliOptions options;
    opterr = 0;  // our own one-line messages
    for (int c; (c = getopt_long(argc, argv, ":o:t:h", long_options, nullptr)) != -1;) {
        const std::string_view value = optarg != nullptr ? optarg : "";
        switch (c) {
        case 'o': options.output_path = std::string(value); break;
        case 't': options.sim.threads = static_cast<int>(parse_unsigned("--threads", value, 1, 1024)); break;
        case opt_seed: options.random.seed = parse_unsigned("--seed", value, 0, UINT64_MAX); break;
        case opt_broadphase:
            if (value == "auto") {
                options.sim.broadphase = Broadphase::automatic;
            } else if (value == "brute") {
                options.sim.broadphase = Broadphase::brute;
            } else if (value == "grid") {
                options.sim.broadphase = Broadphase::grid;
            } else {
                throw BadInput("--broadphase: expected auto, brute or grid, found \"" + std::string(value) + "\"");
            }
            break;
        case opt_grid: options.sim.grid_cells = static_cast<int>(parse_unsigned("--grid", value, 1, max_forced_grid_cells)); break;
        case opt_substeps:
            if (parse_unsigned("--substeps", value, 1, 1u << 20) != 1) {
                throw BadInput("--substeps: only 1 is available in this version (substeps are not implemented yet)");
            }
            break;
        case opt_engine:
            if (value == "exact") throw BadInput("--engine exact: the exact engine is not implemented in this version");
            if (value != "step") throw BadInput("--engine: expected step or exact, found \"" + std::string(value) + "\"");
            break;
        case 'h': std::fputs(usage_text, stdout); return std::nullopt;
        case opt_version: std::printf("simcli %s\n", particlesim::version); return std::nullopt;
        case ':': throw BadInput(std::string("option ") + argv[optind - 1] + " needs a value (see simcli --help)");
        default: throw BadInput(std::string("unknown option ") + argv[optind - 1] + " (see simcli --help)");
        }
    }
    if (argc - optind > 1) throw BadInput("expected at most one scene file, found " + std::to_string(argc - optind) + " (see simcli --help)");
    if (argc - optind == 1) options.scene_path = argv[optind];
    return options;
}

Scene read_input(const std::string& path, const std::string& name) {
    if (path == "-") return read_scene(std::cin);
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw BadInput(name + ": is a directory");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw BadInput(name + ": cannot open: " + std::strerror(errno));
    return read_scene(file);
}

void write_run(std::FILE* out, Simulation& simulation, const SimParams& params) {
    StateWriter writer(out);
    writer.write_state(0, simulation.particles());
    const bool print_mode = params.mode == OutputMode::print;
    simulation.run(params.steps, [&](std::int64_t step, std::span<const Particle> particles) {
        if (print_mode && step < params.steps) writer.write_state(step, particles);
    });
    writer.write_final(params.steps, simulation.particles());
    writer.flush();
}

int run(int argc, char** argv) {
    const std::optional<CliOptions> options = parse_arguments(argc, argv);
    if (!options) return 0;
    const std::string name = options->scene_path == "-" ? "<stdin>" : options->scene_path;

    Scene scene;
    std::vector<Particle> particles;
    try {
        scene = read_input(options->scene_path, name);
        particles = scene.is_random() ? make_random_particles(scene.particle_count, scene.params, options->random)
                                      : std::move(scene.particles);
    } catch (const InputError& e) {
        throw BadInput(name + ":" + std::to_string(e.line()) + ": " + e.what());
    } catch (const SceneTooFull& e) {
        throw BadInput(name + ":" + std::to_string(scene.particle_count_line) + ": " + e.what());
    }
    Simulation simulation(scene.params, std::move(particles), options->sim);

    if (!options->output_path) {
        write_run(stdout, simulation, scene.params);
        return 0;
    }
    std::FILE* out = std::fopen(options->output_path->c_str(), "wb");
    if (out == nullptr) throw OutputError(*options->output_path + ": cannot open for writing: " + std::strerror(errno));
    try {
        write_run(out, simulation, scene.params);
    } catch (...) {
        std::fclose(out);
        throw;
    }
    if (std::fclose(out) != 0) throw OutputError(*options->output_path + ": cannot write: " + std::strerror(errno));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGPIPE, SIG_IGN);  // a closed pipe is a write error (exit 1), not a signal
    try {
        return run(argc, argv);
    } catch (const BadInput& e) {
        std::fprintf(stderr, "simcli: %s\n", e.what());
        return exit_bad_input;
    } catch (const std::exception& e) {  // OutputError and any other failure while running
        std::fprintf(stderr, "simcli: %s\n", e.what());
        return exit_failure;
    }
}
