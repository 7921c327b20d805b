// simcli as a user meets it: output byte for byte as io.md says, print and
// perf agreeing, options, and every class of bad input and failure with its
// exit status, nothing on stdout and one line on stderr.

#include "check.hpp"
#include "example_scenes.hpp"
#include "run_process.hpp"
#include "threads_stats_line.hpp"

#include "core/random.hpp"
#include "particlesim/random_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace particlesim;
using run_process::Result;

namespace {

const std::string simcli = SIMCLI_PATH;
const std::string examples = PARTICLESIM_EXAMPLES_DIR;

Result simcli_run(const std::vector<std::string>& args, const std::string& input = "") {
    return run_process::run(simcli, args, input);
}

bool one_line(const std::string& text) {
    return !text.empty() && text.back() == '\n' && std::count(text.begin(), text.end(), '\n') == 1;
}

// A bad input or usage: exit 2, empty stdout, one line on stderr that starts
// with `prefix` and mentions `fragment`.
void expect_rejected(const std::vector<std::string>& args, const std::string& input, const std::string& prefix,
                     const std::string& fragment) {
    const Result r = simcli_run(args, input);
    CHECK_EQ(r.status, 2);
    CHECK(r.out.empty());
    CHECK(one_line(r.err));
    const bool ok = r.err.rfind(prefix, 0) == 0 && r.err.find(fragment) != std::string::npos;
    CHECK(ok);
    if (!ok) std::fprintf(stderr, "  stderr was: %s", r.err.c_str());
}

// The expected output of `states` (the states of a run of `scene`), formatted
// independently of the library's writer.
std::string expected_output(const Scene& scene, const example_scenes::States& states) {
    std::string text;
    char line[512];
    const auto number = [](double v) {
        char t[64];
        std::snprintf(t, sizeof t, "%.8f", v);
        return std::string(t) == "-0.00000000" ? std::string("0.00000000") : std::string(t);
    };
    const auto add_block = [&](std::int64_t step, const std::vector<Particle>& ps, bool counters) {
        for (std::size_t i = 0; i < ps.size(); ++i) {
            std::snprintf(line, sizeof line, "%lld %zu %s %s %s %s", static_cast<long long>(step), i,
                          number(ps[i].position.x()).c_str(), number(ps[i].position.y()).c_str(),
                          number(ps[i].velocity.x()).c_str(), number(ps[i].velocity.y()).c_str());
            text += line;
            if (counters) {
                std::snprintf(line, sizeof line, " %llu %llu",
                              static_cast<unsigned long long>(ps[i].particle_collisions),
                              static_cast<unsigned long long>(ps[i].wall_collisions));
                text += line;
            }
            text += "\n";
        }
    };
    const std::int64_t steps = scene.steps;
    add_block(0, states[0], false);
    if (scene.mode == OutputMode::print) {
        for (std::int64_t s = 1; s < steps; ++s) add_block(s, states[static_cast<std::size_t>(s)], false);
    }
    add_block(steps, states[static_cast<std::size_t>(steps)], true);
    return text;
}

std::string expected_output(const Scene& scene) { return expected_output(scene, example_scenes::run(scene)); }

std::string last_lines(const std::string& text, std::size_t count) {
    std::size_t at = text.size();
    for (std::size_t k = 0; k <= count && at > 0; ++k) at = text.rfind('\n', at - 1);
    return at == std::string::npos ? text : text.substr(at + 1);
}

std::string with_mode(std::string scene_text, const std::string& from, const std::string& to) {
    scene_text.replace(scene_text.find(from), from.size(), to);
    return scene_text;
}

void examples_byte_for_byte() {
    for (const char* name : {"head_on.in", "crossing.in", "newtons_cradle.in", "glancing_line.in", "square.in",
                             "triangle.in", "corner.in", "faster_than_box.in", "wall_then_pair.in"}) {
        const Result r = simcli_run({examples + "/" + name});
        CHECK_EQ(r.status, 0);
        CHECK(r.err.empty());
        CHECK(r.out == expected_output(example_scenes::load(name)));
        // perf gives the same final block as print.
        const std::string scene_text = run_process::slurp(examples + "/" + name);
        const Result perf = simcli_run({}, with_mode(scene_text, "print", "perf"));
        const std::size_t n = example_scenes::load(name).particle_count;
        CHECK_EQ(perf.status, 0);
        CHECK(last_lines(perf.out, n) == last_lines(r.out, n));
        CHECK_EQ(std::count(perf.out.begin(), perf.out.end(), '\n'), static_cast<long>(2 * n));
    }
}

void random_scenes_and_options() {
    const std::string scene = "300\n20000\n1\n20\nprint\n";
    const Result a = simcli_run({"-"}, scene);
    const Result b = simcli_run({"--seed", "3210", "--threads", "2"}, scene);
    const Result c = simcli_run({"--seed", "7"}, scene);
    CHECK_EQ(a.status, 0);
    CHECK(a.out == b.out);
    CHECK(a.out != c.out);
    CHECK_EQ(std::count(a.out.begin(), a.out.end(), '\n'), 300L * 21);
    // The library's random scene is what simcli printed as the initial state.
    Scene expected;
    expected.world = World{20000.0, 1.0};
    expected.steps = 20;
    expected.mode = OutputMode::print;
    expected.particles = make_random_particles(300, expected.world);
    expected.particle_count = 300;
    CHECK(a.out == expected_output(expected));
    for (const std::string broadphase : {"brute", "grid", "auto"}) {
        for (const std::string threads : {"1", "2", "3"}) {
            CHECK(simcli_run({"--broadphase", broadphase, "-t", threads}, scene).out == a.out);
        }
    }
    CHECK(simcli_run({"--grid", "4", "--engine", "step", "--substeps", "1"}, scene).out == a.out);

    // Substeps and the exact engine print what the library computes.
    const Result substeps = simcli_run({"--substeps", "3", "-t", "2"}, scene);
    CHECK_EQ(substeps.status, 0);
    CHECK(substeps.out == expected_output(expected, example_scenes::run(expected, {.threads = 1, .substeps = 3})));
    CHECK(substeps.out != a.out);
    const Result exact = simcli_run({"--engine", "exact"}, scene);
    CHECK_EQ(exact.status, 0);
    CHECK(exact.out == expected_output(expected, example_scenes::run_exact(expected)));
    CHECK(exact.out != a.out);

    // -o writes the file and nothing to stdout.
    const std::string path = "/tmp/particlesim-test-output.txt";
    const Result to_file = simcli_run({"-o", path}, scene);
    CHECK_EQ(to_file.status, 0);
    CHECK(to_file.out.empty());
    CHECK(run_process::slurp(path) == a.out);
    std::remove(path.c_str());

    // S = 0: the initial state, then the same with zero counters.
    const Result zero = simcli_run({}, "2 20 1 0 print\n0 5 5 1 0\n1 9 9 0 -1\n");
    CHECK(zero.out ==
          "0 0 5.00000000 5.00000000 1.00000000 0.00000000\n0 1 9.00000000 9.00000000 0.00000000 -1.00000000\n"
          "0 0 5.00000000 5.00000000 1.00000000 0.00000000 0 0\n"
          "0 1 9.00000000 9.00000000 0.00000000 -1.00000000 0 0\n");
    CHECK(simcli_run({}, "0 20 1 5 print\n").out.empty());
}

void help_and_version() {
    const Result help = simcli_run({"--help"});
    CHECK_EQ(help.status, 0);
    CHECK(help.out.find("usage: simcli") != std::string::npos);
    CHECK(help.out.find("--broadphase") != std::string::npos);
    const Result version = simcli_run({"--version"});
    CHECK_EQ(version.status, 0);
    CHECK(version.out.rfind("simcli ", 0) == 0);
}

void bad_usage() {
    const std::string scene = "1 20 1 1 perf\n";
    expect_rejected({"--frobnicate"}, scene, "simcli: unknown option --frobnicate", "--help");
    expect_rejected({"--threads", "0"}, scene, "simcli: --threads", "expected an integer in [1, 1024]");
    expect_rejected({"-t", "two"}, scene, "simcli: --threads", "\"two\"");
    expect_rejected({"--seed", "-1"}, scene, "simcli: --seed", "expected an integer");
    expect_rejected({"--broadphase", "octree"}, scene, "simcli: --broadphase", "expected auto, brute, grid or paths");
    expect_rejected({"--grid", "0"}, scene, "simcli: --grid", "[1, 4096]");
    expect_rejected({"--grid", "4097"}, scene, "simcli: --grid", "[1, 4096]");  // refused, not clamped
    expect_rejected({"--broadphase", "brute", "--grid", "4"}, scene, "simcli: --grid", "not with --broadphase brute");
    expect_rejected({"--grid", "4", "--broadphase", "brute"}, scene, "simcli: --grid", "not with --broadphase brute");
    expect_rejected({"--grid", "4", "--broadphase", "paths"}, scene, "simcli: --grid", "not with --broadphase paths");
    CHECK(simcli_run({"--grid", "4", "--broadphase", "grid"}, scene).out == simcli_run({}, scene).out);
    expect_rejected({"--substeps", "0"}, scene, "simcli: --substeps", "expected an integer in [1, 1048576]");
    expect_rejected({"--engine", "exact", "--substeps", "2"}, scene, "simcli: --broadphase, --grid and --substeps",
                    "not to --engine exact");
    expect_rejected({"--grid", "4", "--engine", "exact"}, scene, "simcli: --broadphase", "step engine");
    expect_rejected({"--engine", "magic"}, scene, "simcli: --engine", "expected step or exact");
    expect_rejected({"--output"}, scene, "simcli: option --output needs a value", "");
    expect_rejected({"a.in", "b.in"}, scene, "simcli: expected at most one scene file", "");
    expect_rejected({"/nonexistent/scene.in"}, "", "simcli: /nonexistent/scene.in: cannot open", "No such file");
    expect_rejected({"/tmp"}, "", "simcli: /tmp: is a directory", "");
    const Result directory_in = run_process::run("/bin/sh", {"-c", "exec \"$0\" < /", simcli});
    CHECK_EQ(directory_in.status, 2);
    CHECK_EQ(directory_in.err, std::string("simcli: <stdin>: is a directory\n"));
    expect_rejected({"--trajectory", "/nonexistent/run.xyz"}, scene, "simcli: /nonexistent/run.xyz: cannot create", "");
    expect_rejected({"--trajectory", "run.xyz", "--trajectory-every", "0"}, scene, "simcli: --trajectory-every",
                    "expected an integer in [1, ");
    expect_rejected({"--trajectory-every", "2"}, scene, "simcli: --trajectory-every K needs --trajectory", "");
    // A checkpoint is written when due or on a signal, perhaps hours in: whether it can be is known before the run.
    expect_rejected({"--checkpoint", "/nonexistent/run.ckpt", "--checkpoint-every", "2"}, scene,
                    "simcli: /nonexistent/run.ckpt: cannot create", "");
    expect_rejected({"--checkpoint", "/nonexistent/run.ckpt"}, scene, "simcli: /nonexistent/run.ckpt: cannot create",
                    "");
    expect_rejected({"--checkpoint", "/tmp"}, scene, "simcli: /tmp: cannot open for writing", "Is a directory");
    expect_rejected({"--resume", "state.ckpt", "--snapshot", "run.svg"}, scene,
                    "simcli: --animate and --snapshot need the whole run", "");
    // The exact engine's page setting (any value but 0 and 1 is a mistake, not silently 1).
    setenv("PARTICLESIM_HUGE_PAGES", "off", 1);
    expect_rejected({}, scene, "simcli: PARTICLESIM_HUGE_PAGES: expected 0 (small pages) or 1", "\"off\"");
    for (const char* setting : {"0", "1"}) {
        setenv("PARTICLESIM_HUGE_PAGES", setting, 1);
        CHECK_EQ(simcli_run({}, scene).status, 0);
    }
    unsetenv("PARTICLESIM_HUGE_PAGES");
}

// Each output a file of its own, none the scene or checkpoint read: two
// writers into one file would leave neither's content, and an output over
// its input would replace it. Refused before anything is written, whatever
// the names (a hard link is the same file); devices may be shared.
void outputs_are_files_of_their_own() {
    char name[] = "/tmp/particlesim-cli-XXXXXX";
    const std::string dir = mkdtemp(name);
    const std::string scene = "20 60 1 3 perf\n", scene_path = dir + "/s.in", a = dir + "/a.out", b = dir + "/b.out";
    std::ofstream(scene_path) << scene;
    expect_rejected({"-o", a, "--checkpoint", a}, scene, "simcli: -o " + a + " and --checkpoint " + a,
                    "name the same file: each output needs a file of its own");
    std::ofstream(a) << "kept\n";
    std::filesystem::create_hard_link(a, b);
    expect_rejected({"--engine", "exact", "--trajectory", a, "--observables", b}, scene,
                    "simcli: --trajectory " + a + " and --observables " + b, "name the same file");
    expect_rejected({"-o", b, "--snapshot", a}, scene, "simcli: -o " + b + " and --snapshot " + a,
                    "name the same file");
    expect_rejected({scene_path, "--checkpoint", scene_path}, "",
                    "simcli: --checkpoint " + scene_path + " names the scene file it reads: it would be replaced", "");
    expect_rejected({scene_path, "-o", dir + "/./s.in"}, "", "simcli: -o " + dir + "/./s.in names the scene file", "");
    CHECK(run_process::slurp(a) == "kept\n");
    CHECK(run_process::slurp(scene_path) == scene);
    // A resumed run may checkpoint into the checkpoint it read, not write its output there.
    const std::string checkpoint = dir + "/run.checkpoint";
    CHECK_EQ(simcli_run({"--checkpoint", checkpoint, "--checkpoint-every", "2", "-o", "/dev/null"}, scene).status, 0);
    expect_rejected({"--resume", checkpoint, "-o", checkpoint}, "",
                    "simcli: -o " + checkpoint + " names the checkpoint it resumes: it would be replaced", "");
    CHECK_EQ(simcli_run({"--resume", checkpoint, "--checkpoint", checkpoint}).status, 0);
    // Standard output is one of them (here a file, as the test's runs capture it): -o /dev/stdout writes
    // into that file, never renaming anything over /dev/stdout; a second output there is refused.
    const Result to_stdout = simcli_run({"-o", "/dev/stdout"}, scene);
    CHECK_EQ(to_stdout.status, 0);
    CHECK(to_stdout.out == simcli_run({}, scene).out);
    CHECK(std::filesystem::is_symlink("/dev/stdout"));
    expect_rejected({"--checkpoint", "/dev/stdout"}, scene,
                    "simcli: standard output and --checkpoint /dev/stdout name the same file", "");
    expect_rejected({"-o", "/dev/stdout", "--snapshot", "/dev/stdout"}, scene,
                    "simcli: -o /dev/stdout and --snapshot /dev/stdout name the same file", "");
    CHECK_EQ(simcli_run({"--engine", "exact", "-o", "/dev/null", "--trajectory", "/dev/null", "--observables",
                         "/dev/null", "--checkpoint", "/dev/null"},
                        scene)
                 .status,
             0);
    std::filesystem::remove_all(dir);
}

void bad_input() {
    // One of each class of io.md; the reader test covers every message.
    expect_rejected({}, "", "simcli: <stdin>:1: ", "missing N");
    expect_rejected({}, "x\n", "simcli: <stdin>:1: ", "N: expected a non-negative integer");
    expect_rejected({}, "5\n-20\n", "simcli: <stdin>:2: ", "L = -20 must be > 0");
    expect_rejected({}, "5\n20\n11\n", "simcli: <stdin>:3: ", "2r must be <= L");
    expect_rejected({}, "5\n20\n1\n1.5\n", "simcli: <stdin>:4: ", "S: expected a non-negative integer");
    expect_rejected({}, "5\n20\n1\n1\nfast\n", "simcli: <stdin>:5: ", "expected print or perf");
    expect_rejected({}, "2\n20000\n1\n1000\nperf\n0 -2 5 0 0\n",
                    "simcli: <stdin>:6: ", "particle 0: x = -2 is outside [1, 19999]");
    expect_rejected({}, "2 20 1 1 perf\n0 5 5 0 0\n0 6 6 0 0\n", "simcli: <stdin>:3: ", "listed twice");
    expect_rejected({}, "2 20 1 1 perf\n0 5 5 0 0\n", "simcli: <stdin>:2: ", "found 1");
    expect_rejected({}, "2 20 1 1 perf\n0 5 5 inf 0\n", "simcli: <stdin>:2: ", "finite");
    expect_rejected({}, "4000000000\n20\n1\n1\nperf\n",
                    "simcli: <stdin>:1: ", "more particles than this machine can hold");
    expect_rejected({}, "500\n20\n1\n1\nperf\n", "simcli: <stdin>:1: ", "cannot place 500 non-overlapping disks");
    expect_rejected({}, std::string(100000, '7'), "simcli: <stdin>:1: ", "longer than");
    // A random scene whose speeds would leave the accepted range is refused
    // on the line of r (not printed as garbage).
    expect_rejected({}, "3\n20000\n1e-300\n1\nprint\n", "simcli: <stdin>:3: ", "below the accepted range");
    expect_rejected({}, "3\n1e10\n1e-55\n1\nprint\n", "simcli: <stdin>:3: ", "draws speeds up to L/(8r) = 1.25e+64");
    // Messages: readable numbers, escaped bytes, none cut at a NUL.
    expect_rejected({}, "200\n1e-8\n1e-9\n1\nperf\n",
                    "simcli: <stdin>:1: ", "radius 1e-09 in a box of side 1e-08 (area fraction 6.283");
    expect_rejected({}, "1\n1e-50\n2e-51\n1\nperf\n0 1e-50 5e-51 0 0\n",
                    "simcli: <stdin>:6: ", "x = 1e-50 is outside [2e-51, 8e-51]");
    expect_rejected({},
                    std::string("1 2\0"
                                "0 1 1 perf\n",
                                14),
                    "simcli: <stdin>:1: ", "\"2\\x000\"");
    // Binary garbage is just bad input.
    expect_rejected({}, std::string("\x01\x02\xff\xfe\n", 5), "simcli: <stdin>:1: ", "expected a non-negative integer");
}

void exact_engine() {
    // The hand-built wall-then-pair scene (test_exact_engine works it out).
    const Scene scene = example_scenes::load("wall_then_pair.in");
    const Result r = simcli_run({"--engine", "exact", examples + "/wall_then_pair.in"});
    CHECK_EQ(r.status, 0);
    CHECK(r.out == expected_output(scene, example_scenes::run_exact(scene)));
    CHECK(r.out.find("1 0 95.00000000 50.00000000 0.00000000 0.00000000\n") != std::string::npos);
    // Overlapping disks have no exact ground truth; touching ones do.
    // Every refusal names its line: the first particle of an overlapping pair,
    // the line of S for a run that would not end.
    expect_rejected({"--engine", "exact"}, "2 20 1 1 perf\n1 6 5 0 0\n0 5 5 0 0\n",
                    "simcli: <stdin>:3: particles 0 and 1 overlap", "no two disks overlap");
    CHECK_EQ(simcli_run({"--engine", "exact"}, "2 20 1 1 perf\n0 5 5 0 0\n1 7 5 0 0\n").status, 0);
    // A disk far faster than the box bounces ~1e9 times a step: refused, not hung.
    expect_rejected({"--engine", "exact"}, "1 20 1\n100 perf\n0 5 5 1e10 3\n",
                    "simcli: <stdin>:2: the exact engine would need", "use fewer steps or the step engine");
    // A moving disk that fills the box would bounce forever at one instant.
    expect_rejected({"--engine", "exact"}, "1 2 1 1 perf\n0 1 1 1 0\n",
                    "simcli: <stdin>:1: the exact engine would need", "inf");
    expect_rejected({"--engine", "exact"}, "1 20 1 9007199254740993 perf\n0 5 5 0 0\n",
                    "simcli: <stdin>:1: S = 9007199254740993", "at most 2^53 steps");
    // Two disks in a 1e-9 gap pass the start estimate
    // (1.5 events a step) but bounce ~1e9 times a step: stopped within a
    // second, exit 1, naming the step and the event count against the prediction.
    const Result trapped =
        simcli_run({"--engine", "exact"}, "2\n4.000000001\n1\n1\nprint\n0 1 2 1 0\n1 3.000000001 2 -1 0\n");
    CHECK_EQ(trapped.status, 1);
    CHECK(one_line(trapped.err));
    CHECK(trapped.err.find("simcli: step 1: the exact engine has processed") == 0);
    CHECK(trapped.err.find("predicted") != std::string::npos);
    CHECK_EQ(simcli_run({"--engine", "step"}, "1 2 1 3 perf\n0 1 1 1 0\n").status, 0);
}

unsigned long long field_sum(const std::string& final_block, int field) {
    unsigned long long sum = 0;
    std::size_t at = 0;
    while (at < final_block.size()) {
        const std::size_t end = final_block.find('\n', at);
        std::size_t begin = at;
        for (int k = 0; k < field; ++k) begin = final_block.find(' ', begin) + 1;
        sum += std::stoull(final_block.substr(begin, final_block.find(' ', begin) - begin));
        at = end + 1;
    }
    return sum;
}

void stats() {
    const std::string scene = "200 2000 1 50 perf\n";
    for (const std::string engine : {"step", "exact"}) {
        const Result plain = simcli_run({"--engine", engine}, scene);
        const Result r = simcli_run({"--engine", engine, "--stats"}, scene);
        CHECK_EQ(r.status, 0);
        CHECK(r.out == plain.out);  // stdout untouched
        CHECK_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 6L);
        CHECK(r.err.find("stats: engine " + engine + ", 50 steps in ") == 0);
        CHECK(r.err.find(" steps/s)") != std::string::npos);
        CHECK(r.err.find("relative energy drift ") != std::string::npos);
        CHECK(r.err.find(" candidate pairs tested per step") != std::string::npos);
        // The collision counts are the output's counters: sum pc / 2 and sum wc.
        const std::string final_block = last_lines(r.out, 200);
        const unsigned long long pc = field_sum(final_block, 6) / 2;
        const unsigned long long wc = field_sum(final_block, 7);
        CHECK(pc > 0 && wc > 0);
        CHECK(r.err.find("stats: " + std::to_string(pc) + " particle collisions, " + std::to_string(wc) +
                         " wall collisions") != std::string::npos);
        unsigned drift_digits = 0;
        const std::size_t drift = r.err.find("drift ");
        for (std::size_t k = drift + 6; k < r.err.size() && r.err[k] != '\n'; ++k)
            drift_digits += std::isdigit(r.err[k]) ? 1 : 0;
        CHECK(drift_digits >= 19);  // full precision: 17 significant digits and the exponent
        if (engine == "exact") {
            // Every collision is an event; so are cell crossings and stale predictions.
            const std::size_t events_at = r.err.find("stats: ", r.err.find("candidate pairs tested"));
            unsigned long long events = 0;
            CHECK(events_at != std::string::npos &&
                  std::sscanf(r.err.c_str() + events_at, "stats: %llu events (", &events) == 1);
            CHECK(events >= pc + wc);
            CHECK(r.err.find(" per second\n") != std::string::npos);
        }
    }
    // Which search ran: the automatic choice, or the one asked for. 200 disks
    // in a box of 2000 collide rarely (the paths search, one cell); 2000 in
    // a box of 200 often (the grid, cells).
    const std::string crowded = "2000 200 1 5 perf\n";
    const auto stats_of = [](const std::vector<std::string>& args, const std::string& input) {
        std::vector<std::string> with_stats = args;
        with_stats.push_back("--stats");
        return simcli_run(with_stats, input).err;
    };
    CHECK(stats_of({}, scene).find("stats: pair search paths\n") != std::string::npos);
    CHECK(stats_of({}, crowded).find("stats: pair search grid\n") != std::string::npos);
    CHECK(stats_of({"--broadphase", "brute"}, scene).find("stats: pair search brute\n") != std::string::npos);
    CHECK(stats_of({"--engine", "exact"}, scene).find("stats: neighbours by the particles' lines (one cell)\n") !=
          std::string::npos);
    CHECK(stats_of({"--engine", "exact"}, crowded).find(" x ") != std::string::npos);
    // The threads: as asked; unset, a small scene's timed trials run 8 of
    // their 16 steps on one thread, the first trial after 8 steps.
    CHECK(stats_of({"-t", "1"}, scene).find("stats: threads 1\n") != std::string::npos);
    CHECK(stats_of({"-t", "3"}, scene).find("stats: threads 3\n") != std::string::npos);
    // Unset, OpenMP's default: OMP_NUM_THREADS.
    const threads_stats_line::Line from_openmp =
        threads_stats_line::read(run_process::run("/usr/bin/env", {"OMP_NUM_THREADS=3", simcli, "--stats"}, scene).err);
    CHECK(from_openmp.found);
    CHECK_EQ(from_openmp.threads, 3);
    const threads_stats_line::Line unset = threads_stats_line::read(stats_of({}, scene));
    CHECK(unset.found);
    if (unset.threads > 1) {
        CHECK(unset.trials);
        CHECK(unset.one_thread_steps >= 8 && unset.one_thread_steps <= 50 && unset.steps == 50);
    } else {
        CHECK(unset.threads == 1 && !unset.trials);
    }
}

void write_failures() {
    const std::string scene = "50 20000 1 100 print\n";
    const Result full = run_process::run(simcli, {}, scene, "/dev/full");
    CHECK_EQ(full.status, 1);
    CHECK(one_line(full.err));
    CHECK(full.err.find("cannot write") != std::string::npos);
    const Result closed = run_process::run(simcli, {}, scene, "", true);
    CHECK_EQ(closed.status, 1);
    CHECK(one_line(closed.err));
    const Result bad_path = simcli_run({"-o", "/nonexistent/dir/out.txt"}, scene);
    CHECK_EQ(bad_path.status, 1);
    CHECK(one_line(bad_path.err));
    // The pictures' files are tried before the run, not after it: no step
    // ran, so no checkpoint was written (one is due every 10 steps).
    char pictures_directory[] = "/tmp/particlesim-cli-XXXXXX";
    const std::string pictures = mkdtemp(pictures_directory);
    for (const char* option : {"--snapshot", "--animate"}) {
        check::Context context(option);
        const std::string checkpoint = pictures + "/" + (option + 2) + ".checkpoint";
        const Result picture = simcli_run(
            {option, "/nonexistent/dir/picture", "--checkpoint", checkpoint, "--checkpoint-every", "10"}, scene);
        CHECK_EQ(picture.status, 1);
        CHECK(one_line(picture.err));
        CHECK(picture.err.find("/nonexistent/dir/picture: ") != std::string::npos);
        CHECK(!std::filesystem::exists(checkpoint));
    }
    std::filesystem::remove_all(pictures);
    // A side file that fills up mid-run is named, whichever it is.
    for (const std::vector<std::string>& side :
         std::vector<std::vector<std::string>>{{"--snapshot", "/dev/full"},
                                               {"--animate", "/dev/full"},
                                               {"--trajectory", "/dev/full"},
                                               {"--engine", "exact", "--observables", "/dev/full"},
                                               {"--checkpoint", "/dev/full", "--checkpoint-every", "10"}}) {
        check::Context context(side[0], " ", side[1]);
        const Result filled = simcli_run(side, scene);
        CHECK_EQ(filled.status, 1);
        CHECK(one_line(filled.err));
        CHECK(filled.err.rfind("simcli: /dev/full: cannot write", 0) == 0);
    }
    // Started with stdout closed (`>&-`), the steps are not written into a file opened later as descriptor 1
    // (the trajectory): a write error, as with stdout a closed pipe.
    char directory[] = "/tmp/particlesim-cli-XXXXXX";
    const std::string trajectory = std::string(mkdtemp(directory)) + "/closed-stdout.xyz";
    const std::vector<std::string> with_trajectory{"--engine",           "exact", "--trajectory", trajectory,
                                                   "--trajectory-every", "10"};
    std::vector<std::string> closed_stdout{"-c", "exec \"$0\" \"$@\" >&-", simcli};
    closed_stdout.insert(closed_stdout.end(), with_trajectory.begin(), with_trajectory.end());
    const Result no_stdout = run_process::run("/bin/sh", closed_stdout, scene);
    CHECK_EQ(no_stdout.status, 1);
    CHECK(one_line(no_stdout.err));
    CHECK(no_stdout.err.find("cannot write") != std::string::npos);
    const std::string left = std::filesystem::exists(trajectory) ? run_process::slurp(trajectory) : std::string();
    CHECK_EQ(simcli_run(with_trajectory, scene).status, 0);
    CHECK(left.empty() || left == run_process::slurp(trajectory));
    std::filesystem::remove_all(directory);
}

// 8000 disks piled within 1e-6 of one point make each approaching pair a
// candidate at t = 0 (16 million, 380 MB); the selection decides those
// pairs from the particles instead, so the pile runs under a 300 MB address
// space, with the bytes of a run without the limit. A run that does run out
// of memory (3 million disks) says so in one line, exit 1, and leaves no -o
// file.
void piles_and_out_of_memory() {
#if defined(__SANITIZE_ADDRESS__)
    std::printf("under AddressSanitizer, which reserves terabytes of address space: not checked\n");
#else
    std::string pile = "8000 20000 1 2 print\n";
    particlesim::SplitMix64 rng(5);
    const auto uniform = [&](double low, double high) { return low + (high - low) * rng.uniform(); };
    for (int i = 0; i < 8000; ++i) {
        char line[160];
        // One draw a statement: the order of a call's arguments is the compiler's.
        const double x = 100 + uniform(-1e-6, 1e-6);
        const double y = 100 + uniform(-1e-6, 1e-6);
        const double vx = uniform(-5, 5);
        const double vy = uniform(-5, 5);
        std::snprintf(line, sizeof line, "%d %.17g %.17g %.17g %.17g\n", i, x, y, vx, vy);
        pile += line;
    }
    char directory[] = "/tmp/particlesim-cli-XXXXXX";
    const std::string output = std::string(mkdtemp(directory)) + "/pile.out";
    const Result unlimited = simcli_run({"-t", "1"}, pile);
    CHECK_EQ(unlimited.status, 0);
    const auto limited = [&](const char* threads, const std::string& scene) {
        return run_process::run(
            "/bin/sh", {"-c", "ulimit -v 300000 && exec \"$0\" \"$@\"", simcli, "-t", threads, "-o", output}, scene);
    };
    // On two threads the pair search's workers run out: no crash either.
    for (const char* threads : {"1", "2"}) {
        check::Context context(threads, " threads");
        const Result piled = limited(threads, pile);
        CHECK_EQ(piled.status, 0);
        CHECK(std::filesystem::exists(output) && run_process::slurp(output) == unlimited.out);
        std::filesystem::remove(output);
        const Result starved = limited(threads, "3000000 200000 1 1 perf\n");
        CHECK_EQ(starved.status, 1);
        CHECK(one_line(starved.err));
        CHECK(starved.err.rfind("simcli: out of memory while running", 0) == 0);
        CHECK(!std::filesystem::exists(output));
    }
    std::filesystem::remove_all(directory);
#endif
}

#ifdef SIMCLI_WITHOUT_MPI
// A simcli built without MPI, started by a launcher on several ranks (its
// environment as Open MPI or MPICH sets it), refuses: each rank would run
// the whole scene. The first rank says so in one line, the others say
// nothing; on one rank it runs. (A build with MPI: test_simcli_mpirun.)
void several_ranks_without_mpi() {
    const std::string scene = examples + "/head_on.in";
    const auto launched = [&](const std::vector<std::string>& environment) {
        std::vector<std::string> args = environment;
        args.push_back(simcli);
        args.push_back(scene);
        return run_process::run("/usr/bin/env", args);
    };
    const Result first = launched({"OMPI_COMM_WORLD_SIZE=3", "OMPI_COMM_WORLD_RANK=0"});
    CHECK_EQ(first.status, 2);
    CHECK(first.out.empty());
    CHECK(one_line(first.err));
    CHECK(first.err.find("started on 3 ranks, but built without the distributed engine") != std::string::npos);
    const Result other = launched({"PMI_SIZE=2", "PMI_RANK=1"});
    CHECK_EQ(other.status, 2);
    CHECK(other.out.empty());
    CHECK(other.err.empty());
    const Result one_rank = launched({"OMPI_COMM_WORLD_SIZE=1", "OMPI_COMM_WORLD_RANK=0"});
    CHECK_EQ(one_rank.status, 0);
    CHECK_EQ(one_rank.out, simcli_run({scene}).out);
}
#endif

}  // namespace

int main(int argc, char** argv) {
    run_process::children_without_leak_checks();
    return check::run(argc, argv, "test_cli",
                      {
                          {"examples byte for byte", examples_byte_for_byte},
                          {"random scenes and options", random_scenes_and_options},
                          {"help and version", help_and_version},
                          {"bad usage", bad_usage},
                          // Their error paths end the program early: with leak checks, as the rest are not.
                          {"bad input",
                           [] {
                               const run_process::ChildrenWithLeakChecks leak_checks;
                               bad_input();
                           }},
                          {"outputs are files of their own", outputs_are_files_of_their_own},
                          {"exact engine", exact_engine},
                          {"stats", stats},
                          {"piles and out of memory", piles_and_out_of_memory},
                          {"write failures",
                           [] {
                               const run_process::ChildrenWithLeakChecks leak_checks;
                               write_failures();
                           }},
#ifdef SIMCLI_WITHOUT_MPI
                          {"several ranks without MPI", several_ranks_without_mpi},
#endif
                      });
}
