#include "cli_options.hpp"

#include "distinct_files.hpp"

#include "particlesim/engine.hpp"
#include "particlesim/version.hpp"

#include <getopt.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace simcli {

namespace {

using particlesim::PairSearch;

constexpr std::uint64_t max_substeps = 1u << 20;

constexpr const char* usage_text =
    R"(usage: simcli [OPTIONS] [SCENE]           SCENE: a scene file; '-' or absent: stdin
       simcli --resume CHECKPOINT [OPTIONS]

Simulates N hard disks bouncing elastically in a square box, in discrete steps.

  -o, --output FILE                write the output to FILE instead of stdout (a regular
                                   FILE is replaced only when the run succeeds)
  -t, --threads N                  worker threads (default: OpenMP's default)
      --seed N                     seed of a random scene (default 3210)
      --broadphase auto|brute|grid|paths
                                   pair search (default auto); all give identical output
      --grid G                     the grid search with a G x G grid (1 <= G <= 4096;
                                   4 = the 4 x 4 grid of L/4 cells); not with --broadphase brute
                                   or paths
      --substeps K                 K micro-steps per step (default 1)
      --engine step|exact          exact = continuous-time event-driven engine
                                   (one thread; needs a start without overlaps)
      --boundary walls|periodic    the box's edges (default walls); periodic needs --engine
                                   exact: nearest images meet, printed positions in [0, L)
      --exact-numbers              numbers in the shortest form that reads back to the
                                   same double, instead of 8 decimals
      --checkpoint FILE            write the run's exact state to FILE on SIGINT/SIGTERM/SIGHUP
                                   (then exit 130 / 143 / 129, keeping the output, trajectory
                                   and observables written so far)
      --checkpoint-every K           and after every K steps
      --resume FILE                continue a checkpointed run bit for bit ('-': stdin); writes
                                   the steps after the checkpoint (append them to the first
                                   part), and so do --trajectory and --observables
      --progress / --quiet         force / silence the progress line on stderr (default:
                                   on a terminal, for runs longer than about two seconds)
      --progress-every SECONDS       a progress line every SECONDS, the first after SECONDS
                                   (a batch job's log; default 5 off a terminal)
      --animate FILE.html          also write a self-contained page that plays the run
      --animate-every K            one frame every K steps (default: automatic, the page
                                   under about 50 MB, or only the first and the last frame
                                   where those pass it); with --engine exact also 0.5, 0.25,
                                   ..., 0.001 (1/k): frames between whole steps
      --snapshot FILE.svg          also write one state as an SVG picture
      --snapshot-step N              the state after step N (default: the last)
      --colour-by speed|psi6       what --animate and --snapshot colour the disks by (default
                                   speed); psi6: the local hexatic order's phase as a hue, and
                                   the page plots |psi6| and the pressure beside the box
      --trajectory FILE.xyz        also write the states as extended XYZ frames (OVITO, ASE)
      --trajectory-every K           every K steps (default 1), and the last step
      --observables FILE.csv       with --engine exact: a CSV row every K steps of the collisions,
      --observe-every K              kinetic energy, pressure (virial and walls) and |psi6|
      --measure-from STEP          --stats then gives the pressure over the rows from STEP on
      --stats                      a summary on stderr after the run: steps per
                                   second, collisions, energy drift, pair tests
  -h, --help                       this text, exit 0
      --version                    the version, exit 0

Exit status: 0 success, 1 failure while running (output not writable, a runaway
exact step), 2 bad usage or bad input, 130 / 143 / 129 interrupted by SIGINT / SIGTERM / SIGHUP.
)";

std::uint64_t parse_unsigned(std::string_view option, std::string_view text, std::uint64_t min, std::uint64_t max) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc{} || end != text.data() + text.size() || value < min || value > max) {
        throw BadInput(std::string(option) + ": expected an integer in [" + std::to_string(min) + ", " +
                       std::to_string(max) + "], found \"" + std::string(text) + "\"");
    }
    return value;
}

PairSearch parse_pair_search(std::string_view text) {
    for (const PairSearch search :
         {PairSearch::automatic, PairSearch::brute_force, PairSearch::grid, PairSearch::paths}) {
        if (text == particlesim::pair_search_name(search)) return search;
    }
    throw BadInput("--broadphase: expected auto, brute, grid or paths, found \"" + std::string(text) + "\"");
}

enum LongOnly {
    opt_seed = 256,
    opt_broadphase,
    opt_grid,
    opt_substeps,
    opt_engine,
    opt_stats,
    opt_version,
    opt_exact_numbers,
    opt_checkpoint,
    opt_checkpoint_every,
    opt_resume,
    opt_progress,
    opt_progress_every,
    opt_quiet,
    opt_animate,
    opt_animate_every,
    opt_snapshot,
    opt_snapshot_step,
    opt_colour_by,
    opt_trajectory,
    opt_trajectory_every,
    opt_observables,
    opt_observe_every,
    opt_measure_from,
    opt_boundary,
};

// --animate-every: a whole number of steps, or 1/k of a step (k up to 1000).
double parse_animate_every(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const bool number = !text.empty() && error == std::errc{} && end == text.data() + text.size();
    const bool whole = number && value >= 1.0 && value <= 9e15 && value == std::floor(value);
    const double parts = number && value > 0.0 ? 1.0 / value : 0.0;
    const bool fraction =
        number && value > 0.0 && value < 1.0 && parts <= 1000.5 && std::fabs(parts - std::round(parts)) < 1e-9 * parts;
    if (!whole && !fraction) {
        throw BadInput(
            "--animate-every: expected a whole number of steps, or 1/k of a step for k up to 1000 (0.5, 0.25, ..., "
            "0.001), "
            "found \"" +
            std::string(text) + "\"");
    }
    return value;
}

// --progress-every: a time in seconds, from a millisecond to a year.
double parse_progress_every(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const bool number = !text.empty() && error == std::errc{} && end == text.data() + text.size();
    if (!number || !apps_common::is_progress_interval(value)) {
        throw BadInput("--progress-every: expected seconds from 0.001 to 3.2e7, found \"" + std::string(text) + "\"");
    }
    return value;
}

// What was given, before the rules between options are checked.
struct Given {
    bool step_engine_options = false;  // --broadphase, --grid or --substeps
    bool substeps = false;
    bool engine = false;
    bool seed = false;
    bool progress = false;
    bool quiet = false;
    std::optional<PairSearch> pair_search;
    std::optional<double> animate_every;
    std::optional<std::int64_t> snapshot_step;
    bool colour_by = false;
    std::optional<std::int64_t> trajectory_every;
    std::optional<std::int64_t> observe_every;
    std::optional<std::int64_t> measure_from;
    bool boundary = false;
};

void check_combinations(CliOptions& options, const Given& given) {
    if (options.engine == EngineChoice::exact && given.step_engine_options) {
        throw BadInput("--broadphase, --grid and --substeps belong to the step engine, not to --engine exact");
    }
    // --grid G is a grid search with a G x G grid: with --broadphase grid or
    // auto, not with another search asked for by name.
    if (options.stepped.grid_cells && given.pair_search &&
        (*given.pair_search == PairSearch::brute_force || *given.pair_search == PairSearch::paths)) {
        throw BadInput(std::string("--grid G is the grid search, not with --broadphase ") +
                       particlesim::pair_search_name(*given.pair_search));
    }
    options.stepped.pair_search =
        options.stepped.grid_cells ? PairSearch::grid : given.pair_search.value_or(PairSearch::automatic);
    const bool every = options.progress_every.has_value();
    if (const char* why = apps_common::progress_contradiction(given.progress, given.quiet, every)) throw BadInput(why);
    options.progress = apps_common::progress_choice(given.progress, given.quiet, every);
    if (options.checkpoint_every && !options.checkpoint_path) {
        throw BadInput("--checkpoint-every K needs --checkpoint FILE");
    }
    if (given.animate_every && !options.animation) throw BadInput("--animate-every K needs --animate FILE.html");
    if (options.animation) options.animation->every = given.animate_every;
    if (given.animate_every && *given.animate_every < 1.0 && options.engine != EngineChoice::exact) {
        throw BadInput("--animate-every below 1 needs --engine exact: the step rules have no state between steps");
    }
    if (given.snapshot_step && !options.snapshot_path) throw BadInput("--snapshot-step N needs --snapshot FILE.svg");
    if (given.colour_by && !options.animation && !options.snapshot_path) {
        throw BadInput("--colour-by needs --animate FILE.html or --snapshot FILE.svg");
    }
    options.snapshot_step = given.snapshot_step;
    if (given.trajectory_every && !options.trajectory_path) {
        throw BadInput("--trajectory-every K needs --trajectory FILE.xyz");
    }
    options.trajectory_every = given.trajectory_every.value_or(1);
    if ((given.observe_every || given.measure_from) && !options.observables_path) {
        throw BadInput("--observe-every and --measure-from need --observables FILE.csv");
    }
    options.observe_every = given.observe_every.value_or(1);
    options.measure_from = given.measure_from.value_or(0);
    if (options.observables_path && options.engine != EngineChoice::exact && !options.resume_path) {
        throw BadInput(
            "--observables needs --engine exact: the pressure is that of hard disks, which the step rules are not");
    }
    if (options.boundary == particlesim::Boundary::periodic && options.engine != EngineChoice::exact &&
        !options.resume_path) {
        throw BadInput("--boundary periodic needs --engine exact: the step rules are those of a walled box");
    }
    if (options.resume_path && (options.animation || options.snapshot_path)) {
        throw BadInput("--animate and --snapshot need the whole run; not with --resume");
    }
    if (options.resume_path) {
        if (options.scene_path != "-") throw BadInput("--resume continues a checkpoint; it takes no scene file");
        if (given.engine || given.substeps || given.seed || given.boundary ||
            options.numbers != particlesim::NumberFormat::fixed8) {
            throw BadInput(
                "--engine, --boundary, --substeps, --seed and --exact-numbers come from the checkpoint; not with "
                "--resume");
        }
    }
}

// The library reads PARTICLESIM_HUGE_PAGES (0: small pages for the exact
// engine's arrays); any value but 0 and 1 is a mistake said here, not
// taken silently as 1.
void require_known_huge_pages_setting() {
    const char* setting = std::getenv("PARTICLESIM_HUGE_PAGES");
    if (setting == nullptr) return;
    const std::string_view value(setting);
    if (value != "0" && value != "1")
        throw BadInput("PARTICLESIM_HUGE_PAGES: expected 0 (small pages) or 1 (huge pages, the default), found \"" +
                       std::string(value) + "\"");
}

}  // namespace

std::optional<CliOptions> parse_arguments(int argc, char** argv) {
    static const option long_options[] = {{"output", required_argument, nullptr, 'o'},
                                          {"threads", required_argument, nullptr, 't'},
                                          {"seed", required_argument, nullptr, opt_seed},
                                          {"broadphase", required_argument, nullptr, opt_broadphase},
                                          {"grid", required_argument, nullptr, opt_grid},
                                          {"substeps", required_argument, nullptr, opt_substeps},
                                          {"engine", required_argument, nullptr, opt_engine},
                                          {"stats", no_argument, nullptr, opt_stats},
                                          {"exact-numbers", no_argument, nullptr, opt_exact_numbers},
                                          {"checkpoint", required_argument, nullptr, opt_checkpoint},
                                          {"checkpoint-every", required_argument, nullptr, opt_checkpoint_every},
                                          {"resume", required_argument, nullptr, opt_resume},
                                          {"progress", no_argument, nullptr, opt_progress},
                                          {"progress-every", required_argument, nullptr, opt_progress_every},
                                          {"quiet", no_argument, nullptr, opt_quiet},
                                          {"animate", required_argument, nullptr, opt_animate},
                                          {"animate-every", required_argument, nullptr, opt_animate_every},
                                          {"snapshot", required_argument, nullptr, opt_snapshot},
                                          {"snapshot-step", required_argument, nullptr, opt_snapshot_step},
                                          {"colour-by", required_argument, nullptr, opt_colour_by},
                                          {"trajectory", required_argument, nullptr, opt_trajectory},
                                          {"trajectory-every", required_argument, nullptr, opt_trajectory_every},
                                          {"observables", required_argument, nullptr, opt_observables},
                                          {"observe-every", required_argument, nullptr, opt_observe_every},
                                          {"measure-from", required_argument, nullptr, opt_measure_from},
                                          {"boundary", required_argument, nullptr, opt_boundary},
                                          {"help", no_argument, nullptr, 'h'},
                                          {"version", no_argument, nullptr, opt_version},
                                          {nullptr, 0, nullptr, 0}};
    CliOptions options;
    Given given;
    opterr = 0;  // our own one-line messages
    for (int c; (c = getopt_long(argc, argv, ":o:t:h", long_options, nullptr)) != -1;) {
        const std::string_view value = optarg != nullptr ? optarg : "";
        switch (c) {
        case 'o': options.output_path = std::string(value); break;
        case 't':
            options.stepped.threads = static_cast<int>(parse_unsigned("--threads", value, 1, particlesim::max_threads));
            break;
        case opt_seed:
            given.seed = true;
            options.random.seed = parse_unsigned("--seed", value, 0, UINT64_MAX);
            break;
        case opt_broadphase:
            given.step_engine_options = true;
            given.pair_search = parse_pair_search(value);
            break;
        case opt_grid:
            given.step_engine_options = true;
            options.stepped.grid_cells =
                static_cast<int>(parse_unsigned("--grid", value, 1, particlesim::max_grid_cells));
            break;
        case opt_substeps:
            given.step_engine_options = true;
            given.substeps = true;
            options.stepped.substeps = static_cast<int>(parse_unsigned("--substeps", value, 1, max_substeps));
            break;
        case opt_engine:
            given.engine = true;
            if (value == "step") {
                options.engine = EngineChoice::step;
            } else if (value == "exact") {
                options.engine = EngineChoice::exact;
            } else {
                throw BadInput("--engine: expected step or exact, found \"" + std::string(value) + "\"");
            }
            break;
        case opt_stats: options.stats = true; break;
        case opt_exact_numbers: options.numbers = particlesim::NumberFormat::shortest; break;
        case opt_checkpoint: options.checkpoint_path = std::string(value); break;
        case opt_checkpoint_every:
            options.checkpoint_every =
                static_cast<std::int64_t>(parse_unsigned("--checkpoint-every", value, 1, INT64_MAX));
            break;
        case opt_resume: options.resume_path = std::string(value); break;
        case opt_progress: given.progress = true; break;
        case opt_progress_every: options.progress_every = parse_progress_every(value); break;
        case opt_quiet: given.quiet = true; break;
        case opt_animate: options.animation = AnimationRequest{std::string(value), std::nullopt}; break;
        case opt_animate_every: given.animate_every = parse_animate_every(value); break;
        case opt_snapshot: options.snapshot_path = std::string(value); break;
        case opt_snapshot_step:
            given.snapshot_step = static_cast<std::int64_t>(parse_unsigned("--snapshot-step", value, 0, INT64_MAX));
            break;
        case opt_colour_by: {
            given.colour_by = true;
            const std::string_view name = value;
            if (name != "speed" && name != "psi6")
                throw BadInput("--colour-by: expected speed or psi6, found \"" + std::string(value) + "\"");
            options.colour_by = name == "psi6" ? ColourBy::psi6 : ColourBy::speed;
            break;
        }
        case opt_trajectory: options.trajectory_path = std::string(value); break;
        case opt_trajectory_every:
            given.trajectory_every =
                static_cast<std::int64_t>(parse_unsigned("--trajectory-every", value, 1, INT64_MAX));
            break;
        case opt_boundary: {
            given.boundary = true;
            const std::optional<particlesim::Boundary> boundary = particlesim::boundary_named(value);
            if (!boundary)
                throw BadInput("--boundary: expected walls or periodic, found \"" + std::string(value) + "\"");
            options.boundary = *boundary;
            break;
        }
        case opt_observables: options.observables_path = std::string(value); break;
        case opt_observe_every:
            given.observe_every = static_cast<std::int64_t>(parse_unsigned("--observe-every", value, 1, INT64_MAX));
            break;
        case opt_measure_from:
            given.measure_from = static_cast<std::int64_t>(parse_unsigned("--measure-from", value, 0, INT64_MAX));
            break;
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
    check_combinations(options, given);
    require_distinct_files(options);
    require_known_huge_pages_setting();
    return options;
}

}  // namespace simcli
