// The benchmark harness: times the step loop over a range of scenes, searches
// and thread counts, each case in a child process of its own so that its peak
// memory is its own, and prints CSV (one row per case) on stdout.
//
//   particlesim_bench steps    [--quick]   time per step against N, dense gas
//   particlesim_bench sizes    [--quick]   time per particle-step from 4 to 1e7 particles at the
//                                          default scene's density and speeds, and at area fraction 0.3
//   particlesim_bench choice   [--quick]   the paths search and the grid forced, and which `auto` takes
//   particlesim_bench simcli   [--quick]   whole simcli runs of the target scenes
//   particlesim_bench accuracy [--quick]   run time against error (accuracy_benchmark.cpp)
//   particlesim_bench exact    [--quick]   the exact engine's speed (accuracy_benchmark.cpp)
//   particlesim_bench exact_queue [--quick] the exact engine's two queues forced, around the
//                                          size from which it takes the two-tier one
//                                          (exact_queue_benchmark.cpp)
//   particlesim_bench stress   [--quick]   1e6 steps of a crowded box (stress_benchmark.cpp)
//   particlesim_bench divergence [--quick] two correct programs drifting apart (divergence_benchmark.cpp)
//   particlesim_bench loaded   [--quick]   1 and 2 threads and the default thread count, quiet and
//                                          beside a busy process (programs_benchmark.cpp)
//   particlesim_bench programs [--quick]   beside the original programs and EDMD (programs_benchmark.cpp)
//   particlesim_bench memory   [--quick]   random 64-byte reads at the exact engine's sizes: how many
//                                          a second, and one at a time (memory_benchmark.cpp)
//
// Every time is the median of repeated runs measured in the same invocation.
// A run's first step is timed apart from the steps after it: it allocates
// the buffers, touches their pages for the first time and makes the first
// storage order by position (at 1e7 particles, four times a later step).

#include "benchmarks.hpp"
#include "statistics.hpp"
#include "timed_run.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

using namespace particlesim;

namespace bench {

namespace {

struct Case {
    std::string name;
    std::size_t count;
    double box_size;
    double radius;
    std::int64_t steps;
    std::optional<SpeedRange> speeds;
    PairSearch search;
    int threads;
    int repeats;
};

struct Measurement {
    double median_seconds = 0.0;
    double min_seconds = 0.0;
    double max_seconds = 0.0;
    double first_step_seconds = 0.0;  // median
    double pair_tests_per_step = 0.0;
    double collisions_per_step = 0.0;
};

// Runs in the child: builds the scene (untimed), then times the steps.
Measurement measure(const Case& c) {
    const World params{c.box_size, c.radius};
    RandomSceneOptions scene;
    scene.speeds = c.speeds;
    std::vector<double> seconds;
    std::vector<double> first_step_seconds;
    Measurement m;
    for (int r = 0; r < c.repeats; ++r) {
        // A fresh scene moved into the simulation, so that the peak memory is
        // the simulation's, not that of a copy kept for the next repeat.
        SteppedSimulation sim(params, make_random_particles(c.count, params, scene),
                              {.pair_search = c.search, .threads = c.threads});
        const auto first = std::chrono::steady_clock::now();
        sim.step();
        const auto start = std::chrono::steady_clock::now();
        first_step_seconds.push_back(std::chrono::duration<double>(start - first).count());
        const StepCounts after_first = sim.totals();
        particlesim::run(sim, c.steps);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        m.pair_tests_per_step =
            static_cast<double>(sim.totals().pair_tests - after_first.pair_tests) / static_cast<double>(c.steps);
        m.collisions_per_step =
            static_cast<double>(sim.totals().particle_collisions - after_first.particle_collisions) /
            static_cast<double>(c.steps);
    }
    m.first_step_seconds = median(first_step_seconds);
    m.median_seconds = median(seconds);
    m.min_seconds = *std::min_element(seconds.begin(), seconds.end());
    m.max_seconds = *std::max_element(seconds.begin(), seconds.end());
    return m;
}

// One case measured in a child process of its own (so that the peak memory is
// the case's): its measurement and the child's peak resident bytes, or
// nothing if the child failed.
struct ChildMeasurement {
    Measurement measurement;
    double peak_bytes = 0.0;
};
std::optional<ChildMeasurement> measure_in_child(const Case& c) {
    int channel[2];
    if (pipe(channel) != 0) return std::nullopt;
    const pid_t child = fork();
    if (child == 0) {
        close(channel[0]);
        const Measurement m = measure(c);
        if (write(channel[1], &m, sizeof m) != static_cast<ssize_t>(sizeof m)) _exit(1);
        _exit(0);
    }
    close(channel[1]);
    Measurement m;
    const bool got = read(channel[0], &m, sizeof m) == static_cast<ssize_t>(sizeof m);
    close(channel[0]);
    int status = 0;
    rusage usage{};
    wait4(child, &status, 0, &usage);
    if (!got) {
        std::fprintf(stderr, "case %s failed\n", c.name.c_str());
        return std::nullopt;
    }
    return ChildMeasurement{m, static_cast<double>(usage.ru_maxrss) * 1024.0};
}

// One CSV row: the case and its measurement.
void print_step_case(const Case& c, const Measurement& m, double peak_bytes) {
    const double per_step = m.median_seconds / static_cast<double>(c.steps);
    std::printf("%s,%zu,%g,%g,%lld,%s,%d,%d,%.9g,%.9g,%.9g,%.6g,%.1f,%.4g,%.0f,%.1f,%.9g\n", c.name.c_str(), c.count,
                c.box_size, c.radius, static_cast<long long>(c.steps), pair_search_name(c.search), c.threads, c.repeats,
                per_step, m.min_seconds / static_cast<double>(c.steps), m.max_seconds / static_cast<double>(c.steps),
                static_cast<double>(c.count) / per_step, m.pair_tests_per_step, m.collisions_per_step, peak_bytes,
                peak_bytes / static_cast<double>(c.count), m.first_step_seconds);
    std::fflush(stdout);
}

// A case's repeats in one child, back to back.
void run_step_case(const Case& c) {
    if (const std::optional<ChildMeasurement> measured = measure_in_child(c))
        print_step_case(c, measured->measurement, measured->peak_bytes);
}

// Cases in `rounds` rounds, each case once a round in a child of its own,
// the order reversed every other round: a minute-long slow spell of a noisy
// host then touches one run of several cases instead of every run of one.
// One row a case: the median, lowest and highest of its rounds.
void run_step_cases_in_rounds(std::vector<Case> cases, int rounds) {
    std::vector<std::vector<Measurement>> runs(cases.size());
    std::vector<double> peak_bytes(cases.size(), 0.0);
    for (int round = 0; round < rounds; ++round) {
        for (std::size_t k = 0; k < cases.size(); ++k) {
            const std::size_t index = round % 2 == 0 ? k : cases.size() - 1 - k;
            Case once = cases[index];
            once.repeats = 1;
            if (const std::optional<ChildMeasurement> measured = measure_in_child(once)) {
                runs[index].push_back(measured->measurement);
                peak_bytes[index] = std::max(peak_bytes[index], measured->peak_bytes);
            }
        }
    }
    for (std::size_t index = 0; index < cases.size(); ++index) {
        if (runs[index].empty()) continue;
        std::vector<double> seconds, first_steps;
        for (const Measurement& m : runs[index]) {
            seconds.push_back(m.median_seconds);
            first_steps.push_back(m.first_step_seconds);
        }
        Measurement summary = runs[index].front();  // the counts: the same scene every round
        summary.median_seconds = median(seconds);
        summary.min_seconds = *std::min_element(seconds.begin(), seconds.end());
        summary.max_seconds = *std::max_element(seconds.begin(), seconds.end());
        summary.first_step_seconds = median(first_steps);
        Case printed = cases[index];
        printed.repeats = static_cast<int>(runs[index].size());
        print_step_case(printed, summary, peak_bytes[index]);
    }
}

// The columns run_step_case() prints.
void print_step_case_header() {
    std::printf(
        "case,n,box_size,radius,steps,search,threads,repeats,median_s_per_step,min_s_per_step,max_s_per_step,"
        "particle_steps_per_s,pair_tests_per_step,particle_collisions_per_step,peak_rss_bytes,peak_bytes_per_"
        "particle,first_step_s\n");
}

// Steps so that one run lasts roughly `target` seconds at `per_step` seconds.
std::int64_t steps_for(double per_step_guess, double target, std::int64_t most, std::int64_t least = 3) {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(target / per_step_guess), least, most);
}

}  // namespace

void steps_benchmark(bool quick) {
    print_step_case_header();
    const int repeats = quick ? 3 : 5;
    const double target = quick ? 0.1 : 0.5;
    for (const std::size_t n : {4, 16, 64, 256, 1024, 4096, 16384, 32000}) {
        if (quick && n > 4096) break;
        const double nd = static_cast<double>(n);
        for (const PairSearch search : {PairSearch::brute_force, PairSearch::grid}) {
            if (search == PairSearch::brute_force && n > 16384) continue;  // hours at N = 32000
            for (const int threads : {1, 2}) {
                const double guess = search == PairSearch::brute_force ? 4e-9 * nd * nd + 1e-6 : 4e-7 * nd + 2e-6;
                const Case c{"sparse", n,      20000.0, 1.0,    steps_for(guess, target, 1000000),
                             {},       search, threads, repeats};
                run_step_case(c);
            }
        }
    }
    // Dense gas: area fraction 0.3, speeds 0.1 to 1 r per step.
    const std::size_t dense_n = quick ? 100000 : 1000000;
    const double dense_box = dense_gas_world(dense_n).box_size;
    for (const int threads : {1, 2}) {
        run_step_case({"dense", dense_n, dense_box, 1.0, quick ? 5 : 20, SpeedRange{0.1, 1.0}, PairSearch::grid,
                       threads, quick ? 1 : 3});
    }
}

// Cost against size in two families that keep their character as N grows:
// the default scene's density and speeds (1000 disks in L = 20000, speeds
// 2500 to 5000 a step: the box grows as sqrt(N), while the mean free path,
// the collisions a particle-step and the path a step in particle spacings
// stay) and the gas at area fraction 0.3 (speeds 0.1 r to r). The search is
// the automatic choice, as simcli makes it.
void sizes_benchmark(bool quick) {
    print_step_case_header();
    const std::size_t largest = quick ? 65536 : 10000000;
    const double target = quick ? 0.1 : 1.0;
    std::vector<std::size_t> sizes;
    for (std::size_t n = 4; n <= 4194304; n *= 4) sizes.push_back(n);
    sizes.push_back(10000000);
    std::vector<Case> cases;
    for (const std::size_t n : sizes) {
        if (n > largest) break;
        const double nd = static_cast<double>(n);
        const double default_box = default_density_world(n).box_size;
        const double gas_box = dense_gas_world(n).box_size;
        for (const int threads : {1, 2}) {
            // Guesses of the time a step, for about `target` seconds a run.
            // At least 8 steps: the storage order by position is made afresh
            // every 8 steps (from 65536 particles), a cost of the steady state.
            const double guess = 2e-7 * nd + 2e-6;
            const std::int64_t steps = steps_for(guess, target, 100000, 8);
            cases.push_back({"default density", n, default_box, 1.0, steps, default_scene_speeds, PairSearch::automatic,
                             threads, 1});
            cases.push_back(
                {"area fraction 0.3", n, gas_box, 1.0, steps, SpeedRange{0.1, 1.0}, PairSearch::automatic, threads, 1});
        }
    }
    run_step_cases_in_rounds(std::move(cases), quick ? 1 : 3);
}

// Which search `auto` takes, against both forced, one thread, rounds
// alternating: the rules' random scene at the default density (speeds L/8 to
// L/4, as the rules draw them), the gas at area fraction 0.3, the rules'
// random scene in the default box (L = 20000), and the sizes benchmark's
// family (the default density with the default scene's speeds, 2500 to 5000
// a step) where its choice is close.
void choice_benchmark(bool quick) {
    std::printf(
        "scene,n,box_size,steps,rounds,auto,paths_median_s_per_step,grid_median_s_per_step,slower_over_faster\n");
    struct ChoiceCase {
        std::string name;
        std::size_t count;
        double box_size;
        std::optional<SpeedRange> speeds;
    };
    std::vector<ChoiceCase> cases;
    for (const std::size_t n : {256, 1024, 4096, 16384}) {
        cases.push_back({"default density", n, default_density_world(n).box_size, std::nullopt});
        cases.push_back({"area fraction 0.3", n, dense_gas_world(n).box_size, SpeedRange{0.1, 1.0}});
    }
    for (const std::size_t n : {64, 200, 1000, 2000, 4000, 8000, 16000}) {
        cases.push_back({"L = 20000", n, 20000.0, std::nullopt});
    }
    for (const std::size_t n : {1024, 2048, 4096, 8192, 12000, 16384}) {
        cases.push_back({"default density and speeds", n, default_density_world(n).box_size, default_scene_speeds});
    }
    const int rounds = quick ? 1 : 3;
    for (const ChoiceCase& c : cases) {
        const World world{c.box_size, 1.0};
        RandomSceneOptions options;
        options.speeds = c.speeds;
        const std::vector<Particle> particles = make_random_particles(c.count, world, options);
        const double nd = static_cast<double>(c.count);
        const std::int64_t steps = steps_for(2e-9 * nd * nd / 16.0 + 1e-6, quick ? 0.05 : 0.3, 2000);
        std::vector<double> paths, grid;
        for (int round = 0; round < rounds; ++round) {
            for (int k = 0; k < 2; ++k) {
                const bool run_paths = (k == 0) == (round % 2 == 0);
                SteppedSimulation sim(world, particles,
                                      {.pair_search = run_paths ? PairSearch::paths : PairSearch::grid, .threads = 1});
                const auto start = std::chrono::steady_clock::now();
                particlesim::run(sim, steps);
                const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                (run_paths ? paths : grid).push_back(seconds / static_cast<double>(steps));
            }
        }
        const PairSearch chosen = SteppedSimulation(world, particles, {.threads = 1}).pair_search();
        const double p = median(paths), g = median(grid);
        std::printf("%s,%zu,%g,%lld,%d,%s,%.6g,%.6g,%.3f\n", c.name.c_str(), c.count, c.box_size,
                    static_cast<long long>(steps), rounds, pair_search_name(chosen), p, g,
                    std::max(p, g) / std::min(p, g));
        std::fflush(stdout);
    }
}

std::string simcli_path(const char* mode) {
#ifdef SIMCLI_PATH
    (void)mode;
    return SIMCLI_PATH;
#else
    std::fprintf(stderr, "particlesim_bench %s: built without simcli (PARTICLESIM_BUILD_APPS=OFF)\n", mode);
    std::exit(2);
#endif
}

void simcli_benchmark(bool quick) {
    const std::string simcli = simcli_path("simcli");
    std::printf("scene,options,runs,median_s,min_s,max_s\n");
    const std::string examples = PARTICLESIM_EXAMPLES_DIR;
    const std::string dir = temporary_directory();
    const auto write_scene = [&](const std::string& name, const std::string& text) {
        const std::string path = dir + "/" + name;
        std::FILE* f = std::fopen(path.c_str(), "w");
        std::fputs(text.c_str(), f);
        std::fclose(f);
        return path;
    };
    struct Run {
        std::string scene;
        std::string path;
        std::vector<std::string> options;
        int runs;
    };
    const std::string default_path = examples + "/default.in";
    const std::string default_print = write_scene("default_print.in", "1000 20000 1 1000 print\n");
    const std::string tiny = write_scene("four_1e6.in", quick ? "4 20000 1 100000 perf\n" : "4 20000 1 1000000 perf\n");
    const std::string n32000 = write_scene("n32000.in", "32000 20000 1 1000 perf\n");
    std::vector<Run> runs{
        {"default", default_path, {"-t", "2"}, quick ? 5 : 11},
        {"default", default_path, {"-t", "1"}, quick ? 5 : 11},
        {"default", default_path, {"-t", "2", "--broadphase", "brute"}, 3},
        {"default", default_path, {"--engine", "exact"}, quick ? 3 : 5},
        {"default print", default_print, {"-t", "2"}, quick ? 3 : 7},
        {quick ? "4 particles 1e5 steps" : "4 particles 1e6 steps", tiny, {"-t", "2"}, quick ? 3 : 7}};
    if (!quick) runs.push_back({"N=32000 S=1000", n32000, {"-t", "2"}, 3});
    for (const Run& run : runs) {
        std::vector<std::string> args{simcli};
        args.insert(args.end(), run.options.begin(), run.options.end());
        args.push_back(run.path);
        std::vector<double> seconds;
        for (int k = 0; k < run.runs; ++k) seconds.push_back(run_timed(args, "", "/dev/null").seconds);
        std::string options;
        for (const std::string& o : run.options) options += (options.empty() ? "" : " ") + o;
        std::printf("%s,%s,%d,%.6f,%.6f,%.6f\n", run.scene.c_str(), options.c_str(), run.runs, median(seconds),
                    *std::min_element(seconds.begin(), seconds.end()),
                    *std::max_element(seconds.begin(), seconds.end()));
        std::fflush(stdout);
    }
}

}  // namespace bench

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    const bool quick = argc > 2 && std::strcmp(argv[2], "--quick") == 0;
    if (mode == "steps") {
        bench::steps_benchmark(quick);
    } else if (mode == "sizes") {
        bench::sizes_benchmark(quick);
    } else if (mode == "choice") {
        bench::choice_benchmark(quick);
    } else if (mode == "simcli") {
        bench::simcli_benchmark(quick);
    } else if (mode == "accuracy") {
        bench::accuracy_benchmark(quick);
    } else if (mode == "exact") {
        bench::exact_benchmark(quick);
    } else if (mode == "exact_queue") {
        bench::exact_queue_benchmark(quick);
    } else if (mode == "stress") {
        bench::stress_benchmark(quick);
    } else if (mode == "divergence") {
        bench::divergence_benchmark(quick);
    } else if (mode == "loaded") {
        bench::loaded_benchmark(quick);
    } else if (mode == "programs") {
        bench::programs_benchmark(quick);
    } else if (mode == "memory") {
        bench::memory_benchmark(quick);
    } else {
        std::fprintf(stderr,
                     "usage: particlesim_bench "
                     "steps|sizes|choice|simcli|accuracy|exact|exact_queue|stress|divergence|loaded|programs|memory "
                     "[--quick]\n");
        return 2;
    }
    return 0;
}
