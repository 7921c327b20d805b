// Whole programs, timed side by side in one run:
//   loaded   : simcli on 1 and 2 threads and its default, quiet and beside a busy process
//              that this harness starts and stops itself;
//   programs : simcli against the original team's programs and an
//              event-driven anchor, on the same scene files (the exact
//              engine's default scene: whole runs, against the baseline only).
// Other builds are given by environment variables, each optional (a missing
// one is said on stderr and its rows left out):
//   PARTICLESIM_BASELINE_SIMCLI  an earlier simcli, timed beside this one
//   ORIGINAL_SEQUENTIAL          ariadn3/DiscreteParticleSimulator openmp/sequential
//   ORIGINAL_OPENMP              its openmp/parallel (first argument: threads)
//   EDMD_HARDDISKS               l09rin/EDMD Cylinder2D/harddisks.c (mdhdd)
// PARTICLESIM_BENCH_ONLY=TEXT runs only the scenes whose name contains TEXT.
// docs/benchmarks.md gives the commands that build them outside the repository.

#include "benchmarks.hpp"
#include "statistics.hpp"
#include "timed_run.hpp"

#include "particlesim/random_scene.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/scene_families.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace bench {

namespace {

using namespace particlesim;

// One busy process (a shell loop), as most users' machines have beside them.
class BusyProcess {
public:
    BusyProcess() {
        pid_ = fork();
        if (pid_ == 0) {
            execl("/bin/sh", "sh", "-c", "while :; do :; done", static_cast<char*>(nullptr));
            _exit(127);
        }
        usleep(200000);  // let the scheduler see it
    }
    ~BusyProcess() {
        if (pid_ <= 0) return;
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
    }
    BusyProcess(const BusyProcess&) = delete;
    BusyProcess& operator=(const BusyProcess&) = delete;

private:
    pid_t pid_ = -1;
};

// A scene file with every particle listed, so that every program starts from the same state.
std::string write_scene_file(const std::string& path, const World& world, std::size_t count, std::int64_t steps,
                             std::optional<SpeedRange> speeds) {
    Scene scene;
    scene.world = world;
    scene.steps = steps;
    scene.mode = OutputMode::perf;
    scene.particle_count = count;
    RandomSceneOptions options;
    options.speeds = speeds;
    scene.particles = make_random_particles(count, world, options);
    std::ofstream out(path);
    write_scene(out, scene);
    return path;
}

bool wanted(const std::string& scene) {
    const char* only = std::getenv("PARTICLESIM_BENCH_ONLY");
    return only == nullptr || scene.find(only) != std::string::npos;
}

std::optional<std::string> program_from(const char* variable) {
    const char* value = std::getenv(variable);
    if (value == nullptr || *value == '\0') {
        std::fprintf(stderr, "particlesim_bench: %s not set: its rows are left out\n", variable);
        return std::nullopt;
    }
    return std::string(value);
}

// "stats: 123 particle collisions, 45 wall collisions" -> 168.
double simcli_collisions(const std::string& err) {
    unsigned long long pairs = 0;
    unsigned long long walls = 0;
    const std::size_t at = err.find("stats: ", err.find("stats: ") + 1);
    if (at == std::string::npos ||
        std::sscanf(err.c_str() + at, "stats: %llu particle collisions, %llu wall collisions", &pairs, &walls) != 2)
        return -1.0;
    return static_cast<double>(pairs + walls);
}

// "stats: 1271943 events (...)" -> 1271943; -1 from a simcli that does not
// count its events (builds before they were counted).
double simcli_events(const std::string& err) {
    const std::size_t at = err.find(" events (");
    if (at == std::string::npos) return -1.0;
    const std::size_t line = err.rfind("stats: ", at);
    unsigned long long events = 0;
    if (line == std::string::npos || std::sscanf(err.c_str() + line, "stats: %llu events", &events) != 1) return -1.0;
    return static_cast<double>(events);
}

// The last "Collisions: N" that mdhdd prints.
double edmd_collisions(const std::string& out) {
    const std::size_t at = out.rfind("Collisions: ");
    unsigned long long collisions = 0;
    if (at == std::string::npos || std::sscanf(out.c_str() + at, "Collisions: %llu", &collisions) != 1) return -1.0;
    return static_cast<double>(collisions);
}

struct Row {
    std::string scene;
    std::string program;
    std::string load = "quiet";
    std::vector<double> seconds;
    double work = 0.0;  // particle-steps, collisions or events
    std::string work_unit;
};

void print_header() { std::printf("scene,program,load,runs,median_s,min_s,max_s,work,work_unit,work_per_s\n"); }

void print_row(const Row& row) {
    std::vector<double> ok;
    for (const double s : row.seconds)
        if (s >= 0.0) ok.push_back(s);
    if (ok.empty()) {
        std::printf("%s,%s,%s,0,failed,,,,,\n", row.scene.c_str(), row.program.c_str(), row.load.c_str());
        return;
    }
    const double m = median(ok);
    std::printf("%s,%s,%s,%zu,%.6f,%.6f,%.6f,%.6g,%s,%.6g\n", row.scene.c_str(), row.program.c_str(), row.load.c_str(),
                ok.size(), m, *std::min_element(ok.begin(), ok.end()), *std::max_element(ok.begin(), ok.end()),
                row.work, row.work_unit.c_str(), row.work > 0.0 ? row.work / m : 0.0);
    std::fflush(stdout);
}

}  // namespace

void loaded_benchmark(bool quick) {
    const std::string simcli = simcli_path("loaded");
    const std::string dir = temporary_directory();
    struct Case {
        std::string scene;
        std::string path;
        double particle_steps;
        int runs;
    };
    const World sparse{20000.0, 1.0};
    const std::size_t gas_n = quick ? 100000 : 1000000;
    std::vector<Case> cases{
        {"default", write_scene_file(dir + "/default.in", sparse, 1000, 1000, std::nullopt), 1e6, quick ? 3 : 7},
        {"N=32000 S=100", write_scene_file(dir + "/n32000.in", sparse, 32000, quick ? 20 : 100, std::nullopt),
         32000.0 * (quick ? 20 : 100), 3},
        {"dense gas S=20", write_scene_file(dir + "/gas.in", dense_gas_world(gas_n), gas_n, 20, SpeedRange{0.1, 1.0}),
         static_cast<double>(gas_n) * 20, 3}};
    std::vector<std::pair<std::string, std::string> > programs{{"simcli", simcli}};
    if (const auto baseline = program_from("PARTICLESIM_BASELINE_SIMCLI")) programs.emplace_back("baseline", *baseline);
    // Each program on one thread, on two, and with its own default: a row's name, and its arguments.
    const std::vector<std::pair<std::string, std::vector<std::string> > > thread_counts{
        {" -t 1", {"-t", "1"}}, {" -t 2", {"-t", "2"}}, {" default threads", {}}};

    print_header();
    for (const Case& c : cases) {
        if (!wanted(c.scene)) continue;
        std::vector<Row> rows;
        for (const std::string load : {"quiet", "loaded"}) {
            for (const auto& [name, path] : programs) {
                for (const auto& [suffix, arguments] : thread_counts) {
                    rows.push_back({c.scene, name + suffix, load, {}, c.particle_steps, "particle-steps"});
                }
            }
        }
        // Rounds: every program and thread count quiet, then all again beside the busy process.
        for (int round = 0; round < c.runs; ++round) {
            std::size_t row = 0;
            for (const bool loaded : {false, true}) {
                std::optional<BusyProcess> busy;
                if (loaded) busy.emplace();
                for (const auto& [name, path] : programs) {
                    for (const auto& [suffix, arguments] : thread_counts) {
                        std::vector<std::string> command{path};
                        command.insert(command.end(), arguments.begin(), arguments.end());
                        command.insert(command.end(), {c.path, "-o", "/dev/null"});
                        rows[row++].seconds.push_back(run_timed(command).seconds);
                    }
                }
            }
        }
        for (const Row& row : rows) print_row(row);
    }
}

namespace {

// The programs compared, the scenes' directory and the runs of each.
struct Programs {
    std::string simcli;
    std::optional<std::string> baseline;
    std::optional<std::string> sequential;
    std::optional<std::string> openmp;
    std::optional<std::string> edmd;
    std::string dir;
    int runs;
};

// Stepped scenes: every program reads the same file (all particles listed).
void stepped_rows(const Programs& p, bool quick) {
    struct SteppedCase {
        std::string scene;
        World world;
        std::size_t count;
        std::int64_t steps;
        std::optional<SpeedRange> speeds;
        bool original_too;  // the original programs keep N^2 / 2 pointers: up to N = 32000
    };
    const World sparse{20000.0, 1.0};
    const std::size_t gas_n = quick ? 100000 : 1000000;
    std::vector<SteppedCase> stepped{
        {"default", sparse, 1000, 1000, std::nullopt, true},
        {"N=4000 S=200", sparse, 4000, 200, std::nullopt, true},
        {"N=32000 S=10", sparse, 32000, 10, std::nullopt, true},
        {"dense gas S=20", dense_gas_world(gas_n), gas_n, 20, SpeedRange{0.1, 1.0}, false},
        {"dense gas S=60", dense_gas_world(gas_n), gas_n, 60, SpeedRange{0.1, 1.0}, false}};
    if (!quick) stepped.push_back({"N=32000 S=1000", sparse, 32000, 1000, std::nullopt, false});
    for (const SteppedCase& c : stepped) {
        if (!wanted(c.scene)) continue;
        const std::string path = write_scene_file(p.dir + "/scene.in", c.world, c.count, c.steps, c.speeds);
        const std::string text = run_process::slurp(path);
        struct Command {
            std::string name;
            std::vector<std::string> args;
            bool stdin_scene;
        };
        std::vector<Command> commands;
        for (const char* threads : {"1", "2"}) {
            commands.push_back({std::string("simcli -t ") + threads, {p.simcli, "-t", threads, path}, false});
            if (p.baseline)
                commands.push_back({std::string("baseline -t ") + threads, {*p.baseline, "-t", threads, path}, false});
        }
        if (c.original_too && p.sequential) commands.push_back({"original sequential", {*p.sequential}, true});
        if (c.original_too && p.openmp) commands.push_back({"original OpenMP 2 threads", {*p.openmp, "2"}, true});
        const int case_runs = c.steps >= 1000 && c.count >= 32000 ? 1 : (c.count >= 1000000 ? 3 : p.runs);
        std::vector<Row> rows;
        for (const Command& command : commands) {
            rows.push_back(
                {c.scene, command.name, "quiet", {}, static_cast<double>(c.count * c.steps), "particle-steps"});
        }
        for (int round = 0; round < case_runs; ++round) {
            for (std::size_t k = 0; k < commands.size(); ++k) {
                rows[k].seconds.push_back(run_timed(commands[k].args, commands[k].stdin_scene ? text : "").seconds);
            }
        }
        for (const Row& row : rows) print_row(row);
    }
}

void exact_rows(const Programs& p, bool quick) {
    // The exact engine against EDMD's hard disks, area fraction 0.3. EDMD's
    // box is periodic and its disks have diameter 1 and temperature 1: run
    // for a time that gives about as many collisions as ours. Both rates are
    // collisions over (run - the same program's run of length 0).
    struct ExactCase {
        std::size_t count;
        std::int64_t steps;
        double edmd_time;
    };
    std::vector<ExactCase> exact{{10000, 200, 43.0}, {100000, 20, 4.3}};
    if (!quick) exact.push_back({1000000, 4, 0.9});
    for (const ExactCase& c : exact) {
        const std::string scene = "exact N=" + std::to_string(c.count) + " area fraction 0.3";
        if (!wanted(scene)) continue;
        const World world = dense_gas_world(c.count);
        const std::string path = write_scene_file(p.dir + "/exact.in", world, c.count, c.steps, SpeedRange{0.1, 1.0});
        const std::string empty = write_scene_file(p.dir + "/exact0.in", world, c.count, 0, SpeedRange{0.1, 1.0});
        const std::string edmd_input = p.dir + "/edmd.dat";
        const std::string edmd_empty = p.dir + "/edmd0.dat";
        const auto edmd_parameters = [&](const std::string& file, double time) {
            std::ofstream out(file);
            out << "N_particles " << c.count << "\narea_fraction 0.3\ninitial_configuration random\ntime " << time
                << "\nsnapshots 1\nwrite_interval " << (time > 0.0 ? time : 1.0) << "\nseed 7\n";
        };
        edmd_parameters(edmd_input, c.edmd_time);
        edmd_parameters(edmd_empty, 0.0);
        Row ours{scene, "simcli --engine exact", "quiet", {}, 0.0, "collisions"};
        // The same runs counted in events (collisions, cell crossings, stale
        // predictions), the unit the target is set in.
        Row ours_events{scene, "simcli --engine exact", "quiet", {}, 0.0, "events"};
        Row theirs{scene, "EDMD mdhdd", "quiet", {}, 0.0, "collisions"};
        Row ours_previous{scene, "baseline --engine exact", "quiet", {}, 0.0, "collisions"};
        const int exact_runs = c.count >= 1000000 ? 3 : p.runs;
        for (int round = 0; round < exact_runs; ++round) {
            // Returns the run's --stats lines.
            const auto time_simcli = [&](const std::string& program, Row& row) {
                const Timed run = run_timed({program, "--engine", "exact", "--stats", path, "-o", "/dev/null"});
                const Timed setup = run_timed({program, "--engine", "exact", empty, "-o", "/dev/null"});
                row.work = simcli_collisions(run.err);
                row.seconds.push_back(run.seconds < 0 || setup.seconds < 0 ? -1.0 : run.seconds - setup.seconds);
                return run.err;
            };
            const std::string stats = time_simcli(p.simcli, ours);
            ours_events.seconds.push_back(ours.seconds.back());
            ours_events.work = simcli_events(stats);
            if (p.baseline) time_simcli(*p.baseline, ours_previous);
            if (p.edmd) {
                // mdhdd writes its snapshots into the working directory.
                const std::string in_dir = "cd " + p.dir + " && exec " + *p.edmd + " ";
                const Timed run = run_timed({"/bin/sh", "-c", in_dir + edmd_input});
                const Timed setup = run_timed({"/bin/sh", "-c", in_dir + edmd_empty});
                theirs.work = edmd_collisions(run.out);
                theirs.seconds.push_back(run.seconds < 0 || setup.seconds < 0 ? -1.0 : run.seconds - setup.seconds);
            }
        }
        print_row(ours);
        if (ours_events.work > 0.0) print_row(ours_events);
        if (p.baseline) print_row(ours_previous);
        if (p.edmd) print_row(theirs);
    }
}

void exact_default_scene_rows(const Programs& p) {
    const World sparse{20000.0, 1.0};
    // The exact engine on the default scene: walls, which EDMD's periodic box has not.
    if (wanted("exact default scene")) {
        const std::string path = write_scene_file(p.dir + "/default.in", sparse, 1000, 1000, std::nullopt);
        std::vector<std::pair<std::string, std::string> > programs{{"simcli --engine exact", p.simcli}};
        if (p.baseline) programs.emplace_back("baseline --engine exact", *p.baseline);
        std::vector<Row> rows;
        for (const auto& [name, program] : programs)
            rows.push_back({"exact default scene", name, "quiet", {}, 0.0, "collisions"});
        for (int round = 0; round < p.runs; ++round) {
            for (std::size_t k = 0; k < programs.size(); ++k) {
                const Timed run =
                    run_timed({programs[k].second, "--engine", "exact", "--stats", path, "-o", "/dev/null"});
                rows[k].work = simcli_collisions(run.err);
                rows[k].seconds.push_back(run.seconds);
            }
        }
        for (const Row& row : rows) print_row(row);
    }
}

}  // namespace

void programs_benchmark(bool quick) {
    const Programs programs{simcli_path("programs"),
                            program_from("PARTICLESIM_BASELINE_SIMCLI"),
                            program_from("ORIGINAL_SEQUENTIAL"),
                            program_from("ORIGINAL_OPENMP"),
                            program_from("EDMD_HARDDISKS"),
                            temporary_directory(),
                            quick ? 3 : 5};
    print_header();
    stepped_rows(programs, quick);
    exact_rows(programs, quick);
    exact_default_scene_rows(programs);
}

}  // namespace bench
