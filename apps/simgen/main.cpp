// simgen: writes test scenes (io.md "simgen", docs/checking.md).
//   simgen FAMILY [OPTIONS]   one scene, every particle listed in exact numbers, to stdout
//   simgen suite DIR          a graded suite with expected outputs and a manifest
// Thin by design: the families live in the library (scene_families.hpp).

#include "common/library_message.hpp"
#include "common/standard_streams.hpp"
#include "compression_progress.hpp"
#include "suite.hpp"

#include "particlesim/particlesim.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace particlesim;

constexpr int exit_failure = 1;
constexpr int exit_bad_usage = 2;

class BadUsage : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The suite cases a --only list names (comma-separated), each known.
std::vector<std::string> suite_cases_named(const std::string& list) {
    const std::vector<std::string> known = simgen::suite_case_names();
    std::vector<std::string> names;
    std::size_t begin = 0;
    while (begin <= list.size()) {
        const std::size_t end = std::min(list.find(',', begin), list.size());
        const std::string name = list.substr(begin, end - begin);
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            std::string all;
            for (const std::string& k : known) all += (all.empty() ? "" : ", ") + k;
            throw BadUsage("--only: no suite case \"" + name + "\" (the cases: " + all + ")");
        }
        names.push_back(name);
        begin = end + 1;
    }
    return names;
}

void print_usage() {
    std::printf(
        "usage: simgen FAMILY [OPTIONS]    write one scene to stdout\n"
        "       simgen suite DIR [--seed K] [--only NAME,...]\n"
        "                                   write a graded suite: NN-name.in, NN-name.out, manifest.tsv\n"
        "                                   (--only: just the cases named, each keeping its number)\n"
        "\n"
        "Every particle is listed, every number in the shortest text that reads back\n"
        "to the same double: the scene means the same to every program.\n"
        "\n"
        "families:\n");
    for (const SceneFamilyInfo& info : scene_families()) std::printf("  %-9s %s\n", info.name, info.description);
    std::printf(
        "\n"
        "options (a family refuses one it has no use for; --seed goes to every family):\n"
        "  -n, --particles N      number of disks (every family but ties)\n"
        "  -s, --steps S          steps (default 100)\n"
        "      --mode print|perf  output mode (default print)\n"
        "      --seed K           seed (default 3210)\n"
        "  -r, --radius R         radius (default 1)\n"
        "  -L, --box L            side of the box (random, line, fast, walls)\n"
        "      --fraction F       area fraction (gas, clusters; crystal, compressed: below close packing)\n"
        "      --speed-min V      lowest speed, length per step (not ties, crystal, compressed)\n"
        "      --speed-max V      highest speed\n"
        "      --temperature T    crystal, compressed: kT of the Maxwell velocities, mass 1 (default r^2/4)\n"
        "      --boundary B       crystal, compressed: walls (default) or periodic, a start that fills a\n"
        "                         periodic box (run it with simcli --engine exact --boundary periodic)\n"
        "      --growth-rate G    compressed: the diameter's growth per unit time in thermal speeds\n"
        "                         (default 0.01; faster jams sooner into a random packing)\n"
        "      --progress / --quiet\n"
        "                         compressed: force / silence the area fraction reached, on stderr\n"
        "                         (default: on a terminal, for compressions longer than about 2 s)\n"
        "      --progress-every SECONDS\n"
        "                         compressed: a progress line every SECONDS, the first after SECONDS\n"
        "  -h, --help             this text\n"
        "      --version          the version\n");
}

template <typename T>
T parse_number(const std::string& option, const std::string& text) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    const bool parsed = error == std::errc() && end == text.data() + text.size();
    if constexpr (std::is_integral_v<T>) {
        // Counts, steps and seeds: whole numbers from 0 within the type's range.
        if (!parsed || value < T{0}) {
            throw BadUsage(option + " needs a whole number from 0 to " + std::to_string(std::numeric_limits<T>::max()) +
                           ", not \"" + text + "\"");
        }
    }
    if (!parsed) throw BadUsage(option + " needs a number, not \"" + text + "\"");
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) throw BadUsage(option + " needs a finite number, not \"" + text + "\"");
    }
    return value;
}

int run(int argc, char** argv) {
    if (argc < 2) throw BadUsage("needs a FAMILY or \"suite DIR\" (simgen --help)");
    const std::string first = argv[1];
    for (int k = 1; k < argc; ++k) {
        if (std::string(argv[k]) == "-h" || std::string(argv[k]) == "--help") {
            print_usage();
            return 0;
        }
    }
    if (first == "--version") {
        std::printf("simgen %s\n", particlesim::version);
        return 0;
    }
    SceneFamilyOptions options;
    std::optional<double> speed_min, speed_max;
    bool progress = false, quiet = false;
    std::optional<double> progress_every;
    std::optional<std::string> suite_directory;
    std::vector<std::string> only_cases;
    int k = 2;
    if (first == "suite") {
        if (argc < 3) throw BadUsage("suite needs a directory");
        suite_directory = argv[2];
        if (suite_directory->starts_with('-')) {
            throw BadUsage("suite needs a directory first, not the option " + *suite_directory +
                           " (a directory whose name starts with - is ./" + *suite_directory + ")");
        }
        k = 3;
    }
    for (; k < argc; ++k) {
        const std::string arg = argv[k];
        const auto value = [&]() -> std::string {
            if (k + 1 >= argc) throw BadUsage(arg + " needs a value");
            return argv[++k];
        };
        if (suite_directory && arg != "--seed" && arg != "--only") {
            throw BadUsage("suite takes only --seed and --only, not " + arg);
        }
        if (arg == "--only") {
            if (!suite_directory) throw BadUsage("--only belongs to simgen suite");
            only_cases = suite_cases_named(value());
        } else if (arg == "-n" || arg == "--particles") {
            options.particles = parse_number<std::size_t>(arg, value());
        } else if (arg == "-s" || arg == "--steps") {
            options.steps = parse_number<std::int64_t>(arg, value());
        } else if (arg == "--mode") {
            const std::string mode = value();
            if (mode != "print" && mode != "perf") throw BadUsage("--mode is print or perf, not \"" + mode + "\"");
            options.mode = mode == "print" ? OutputMode::print : OutputMode::perf;
        } else if (arg == "--seed") {
            options.seed = parse_number<std::uint64_t>(arg, value());
        } else if (arg == "-r" || arg == "--radius") {
            options.radius = parse_number<double>(arg, value());
        } else if (arg == "-L" || arg == "--box") {
            options.box_size = parse_number<double>(arg, value());
        } else if (arg == "--fraction") {
            options.area_fraction = parse_number<double>(arg, value());
        } else if (arg == "--speed-min") {
            speed_min = parse_number<double>(arg, value());
        } else if (arg == "--speed-max") {
            speed_max = parse_number<double>(arg, value());
        } else if (arg == "--temperature") {
            options.temperature = parse_number<double>(arg, value());
        } else if (arg == "--growth-rate") {
            options.growth_rate = parse_number<double>(arg, value());
        } else if (arg == "--progress") {
            progress = true;
        } else if (arg == "--quiet") {
            quiet = true;
        } else if (arg == "--progress-every") {
            const std::string text = value();
            const double seconds = parse_number<double>(arg, text);
            if (!apps_common::is_progress_interval(seconds))
                throw BadUsage("--progress-every needs seconds from 0.001 to 3.2e7, not \"" + text + "\"");
            progress_every = seconds;
        } else if (arg == "--boundary") {
            const std::string name = value();
            const std::optional<Boundary> boundary = boundary_named(name);
            if (!boundary) throw BadUsage("--boundary is walls or periodic, not \"" + name + "\"");
            options.boundary = *boundary;
        } else {
            throw BadUsage("unknown option " + arg + " (simgen --help lists them)");
        }
    }
    if (suite_directory) {
        simgen::write_suite(*suite_directory, options.seed, only_cases);
        return 0;
    }
    const std::optional<SceneFamily> family = scene_family_named(first);
    if (!family) throw BadUsage("unknown family \"" + first + "\" (simgen --help lists them)");
    if (const char* why = apps_common::progress_contradiction(progress, quiet, progress_every.has_value()))
        throw BadUsage(why);
    std::optional<simgen::CompressionProgress> shown;
    if (*family == SceneFamily::compressed) {
        shown.emplace(apps_common::progress_choice(progress, quiet, progress_every.has_value()), progress_every);
        if (shown->enabled()) {
            options.compression_progress = [&shown](double reached, double target) { shown->update(reached, target); };
        }
    }
    if (speed_min || speed_max) {
        const double low = speed_min.value_or(speed_max.value_or(0.0));
        options.speeds = SpeedRange{low, speed_max.value_or(low)};
    }
    Scene scene;
    try {
        scene = make_family_scene(*family, options);
    } catch (const std::invalid_argument& e) {
        throw BadUsage(first + ": " + e.what());
    } catch (const SceneTooFull& e) {
        throw BadUsage(first + ": " + e.what());
    }
    shown.reset();  // the line cleared before the scene is written
    write_scene(std::cout, scene);
    std::cout.flush();
    if (!std::cout) {
        std::fprintf(stderr, "simgen: cannot write the scene to stdout\n");
        return exit_failure;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // A scene file must not take the number of a closed standard stream.
    if (!apps_common::open_closed_standard_streams()) return 2;
    try {
        return run(argc, argv);
    } catch (const BadUsage& e) {
        std::fprintf(stderr, "simgen: %s\n", apps_common::without_library_names(e.what()).c_str());
        return exit_bad_usage;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "simgen: not enough memory for the scene asked for\n");
        return exit_failure;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "simgen: %s\n", apps_common::without_library_names(e.what()).c_str());
        return exit_failure;
    }
}
