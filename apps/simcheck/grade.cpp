#include "grade.hpp"

#include "command_line.hpp"
#include "common/library_message.hpp"
#include "files_held.hpp"
#include "judge.hpp"
#include "own_user.hpp"
#include "private_files.hpp"
#include "program_environment.hpp"
#include "report.hpp"
#include "sandbox.hpp"

#include "particlesim/scene.hpp"
#include "particlesim/step_check.hpp"

#include <linux/capability.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace simcheck {

namespace {

namespace fs = std::filesystem;

constexpr const char* usage = R"(usage: simcheck grade SUITE_DIR [OPTIONS] -- PROGRAM [ARGS...]

Runs PROGRAM once per scene (every *.in of SUITE_DIR, by name), the scene on
its standard input, or, where an argument is {}, the scene's path there
(stdin is then empty). Judges each output against the rules, times it
against simcli on the same scene, and prints a table. simgen's manifest.tsv
names what each scene exercises; an expected output NAME.out sets the cap on
output size.

Each run gets a fresh empty working directory, its own process group with no
controlling terminal (killed as a whole when it ends), and limits:
      --timeout S        wall-clock seconds per scene (default: 50 times
                         simcli's time on the scene, at least 10; 60 without simcli)
      --output-factor K  stdout capped at K times the expected output's size,
                         plus 1 MiB (default 4); each file it writes, and its
                         files together, too, but at least 1 GiB
      --memory MB        address space of each process, and the memory its
                         processes hold together, pipes' and sockets' buffers
                         too (default 4096; 0: no limit, for programs built
                         with AddressSanitizer, which reserves terabytes)
      --processes N      processes and threads it may add (default 256)
Run by root, each program runs as a user of its own (an unused user id that
may read every file but write only in its directory and where anyone may).
Where the kernel lets it make namespaces (root's, or a user namespace for
anyone else), each runs without network, sees only its own processes, and
has the suite's expected outputs, the other outputs and what only owners may
read in /etc and the homes hidden. Each may
write only in /tmp, /var/tmp, /dev/shm and $TMPDIR (its directory is there),
and signal only its own processes, where the kernel has the means
(docs/checking.md).
Reports:
      --json FILE        {"program", "scenes": [{"scene", "verdict", "step", ...}]}
      --markdown FILE    a table and the details, for pasting
      --outputs DIR      keep each output as DIR/NAME.out (DIR not the suite)
Environment: not the grader's whole one (it may hold secrets the program could
print): PATH, the locale (LANG, LC_*), TZ, TMPDIR, LD_LIBRARY_PATH, OpenMP's,
MPI's and the sanitizers' settings (OMP_*, OMPI_*, PMIX_*, *SAN_OPTIONS, ...),
and HOME set to its working directory.
      --env NAME         also pass NAME (set here); --env NAME=VALUE: set it
      --full-env         pass the grader's whole environment, HOME too
Other:
      --jobs N           run N scenes side by side (the times then say so)
      --reference PATH   the simcli to time against (default: beside simcheck,
                         else on PATH); --no-reference: no ratios
      --substeps K, --engine exact, --boundary periodic   as for simcheck SCENE OUTPUT

Verdicts: conforms; shape (the physics conforms, the output's shape deviates:
named); wrong (breaks the rules; step = the first wrong step); crashed (a
signal); timeout; output-limit; malformed (the output cannot be read);
exit-status (a non-zero exit, whatever the output); no-verdict.
exit status: 0 every scene conforms; 1 otherwise; 2 bad usage.
)";

struct Options {
    fs::path suite;
    std::vector<std::string> program;
    std::optional<double> timeout;
    double output_factor = 4.0;
    std::int64_t memory_mb = 4096;
    int processes = 256;
    int jobs = 1;
    std::string json_path, markdown_path, outputs_dir;
    // What a program must not read: the expected outputs, the outputs' directories.
    HiddenPaths hidden;
    std::string reference;
    bool no_reference = false;
    std::string program_text;  // as given, for the reports
    EnvironmentChoice environment;
    particlesim::StepCheckOptions check;
};

// A bound as a user writes it: 0.01 and 1000000, not 0.010000 and 1000000.000000.
template <typename Number>
std::string bound_text(Number bound) {
    if constexpr (std::is_floating_point_v<Number>) {
        char text[32];
        std::snprintf(text, sizeof text, "%.15g", static_cast<double>(bound));
        return text;
    } else {
        return std::to_string(bound);
    }
}

template <typename Number>
Number number_option(const std::string& name, const std::string& text, Number low, Number high) {
    Number value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !(value >= low && value <= high)) {
        throw BadUsage(name + " needs a number from " + bound_text(low) + " to " + bound_text(high) + ", not \"" +
                       text + "\"");
    }
    return value;
}

std::optional<Options> parse(int argc, char** argv) {
    Options o;
    bool substeps_given = false;
    std::vector<std::string> positional;
    int k = 1;
    for (; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--") {
            ++k;
            break;
        }
        const auto value = [&] { return option_value(argc, argv, k); };
        if (arg == "-h" || arg == "--help") {
            std::fputs(usage, stdout);
            return std::nullopt;
        }
        if (arg == "--timeout") {
            o.timeout = number_option<double>(arg, value(), 0.01, 1e6);
        } else if (arg == "--output-factor") {
            o.output_factor = number_option<double>(arg, value(), 1.0, 1e6);
        } else if (arg == "--memory") {
            o.memory_mb = number_option<std::int64_t>(arg, value(), 0, std::int64_t{1} << 30);
            if (o.memory_mb > 0 && o.memory_mb < 16) throw BadUsage("--memory needs 0 (no limit) or at least 16 MB");
        } else if (arg == "--processes") {
            o.processes = number_option<int>(arg, value(), 1, 1 << 20);
        } else if (arg == "--jobs") {
            o.jobs = number_option<int>(arg, value(), 1, 1024);
        } else if (arg == "--json") {
            o.json_path = value();
        } else if (arg == "--markdown") {
            o.markdown_path = value();
        } else if (arg == "--outputs") {
            o.outputs_dir = value();
        } else if (arg == "--reference") {
            o.reference = value();
        } else if (arg == "--no-reference") {
            o.no_reference = true;
        } else if (arg == "--env") {
            try {
                add_environment_option(value(), o.environment);
            } catch (const std::invalid_argument& e) {
                throw BadUsage("--env: " + std::string(e.what()));
            }
        } else if (arg == "--full-env") {
            o.environment.full = true;
        } else if (read_rules_option(arg, value, o.check)) {
            substeps_given = substeps_given || arg == "--substeps";
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw BadUsage("unknown option " + arg + " (simcheck grade --help lists them)");
        } else {
            positional.push_back(arg);
        }
    }
    for (; k < argc; ++k) o.program.emplace_back(argv[k]);
    require_consistent_rules(o.check, substeps_given);
    if (positional.size() != 1) throw BadUsage("needs one SUITE_DIR (simcheck grade --help)");
    if (o.program.empty()) throw BadUsage("needs -- PROGRAM [ARGS...] after the options (simcheck grade --help)");
    o.suite = positional[0];
    return o;
}

// Where a program of this name would be run from: a path as given, or PATH
// (a directory is searchable, not runnable).
std::optional<std::string> find_program(const std::string& name) {
    if (name.find('/') != std::string::npos) {
        return access(name.c_str(), X_OK) == 0 && !fs::is_directory(name) ? std::optional<std::string>(name)
                                                                          : std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::string_view dirs = path ? path : "/usr/bin:/bin";
    while (!dirs.empty()) {
        const std::size_t colon = dirs.find(':');
        const std::string dir(dirs.substr(0, colon));
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
        dirs = colon == std::string_view::npos ? std::string_view{} : dirs.substr(colon + 1);
    }
    return std::nullopt;
}

std::optional<std::string> find_reference(const Options& o) {
    if (o.no_reference) return std::nullopt;
    if (!o.reference.empty()) {
        if (auto found = find_program(o.reference)) return found;
        throw BadUsage("--reference " + o.reference + ": no such program");
    }
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (!error) {
        const fs::path beside = self.parent_path() / "simcli";
        if (access(beside.c_str(), X_OK) == 0) return beside.string();
        const fs::path build_tree = self.parent_path().parent_path() / "simcli" / "simcli";
        if (access(build_tree.c_str(), X_OK) == 0) return build_tree.string();
    }
    return find_program("simcli");
}

struct SceneCase {
    std::string name;  // the file's stem, e.g. "07-gas"
    fs::path scene_path;
    std::optional<fs::path> expected_path;
    std::string exercises;
    particlesim::Scene scene;
};

std::map<std::string, std::string> read_manifest(const fs::path& suite) {
    std::map<std::string, std::string> exercises;
    std::ifstream manifest(suite / "manifest.tsv");
    std::string line;
    bool header = true;
    while (std::getline(manifest, line)) {
        if (header) {
            header = false;
            continue;
        }
        const std::size_t tab = line.find('\t'), last_tab = line.rfind('\t');
        if (tab == std::string::npos) continue;
        exercises[line.substr(0, tab)] = line.substr(last_tab + 1);
    }
    return exercises;
}

std::vector<SceneCase> read_suite(const fs::path& suite, particlesim::Boundary boundary) {
    std::error_code error;
    if (!fs::is_directory(suite, error)) throw BadUsage(suite.string() + ": not a directory");
    std::vector<SceneCase> cases;
    const std::map<std::string, std::string> exercises = read_manifest(suite);
    for (const fs::directory_entry& entry : fs::directory_iterator(suite)) {
        if (!entry.is_regular_file() || entry.path().extension() != ".in") continue;
        SceneCase c;
        c.name = entry.path().stem().string();
        c.scene_path = fs::absolute(entry.path());
        fs::path expected = entry.path();
        expected.replace_extension(".out");
        if (fs::is_regular_file(expected)) c.expected_path = expected;
        if (const auto it = exercises.find(c.name); it != exercises.end()) c.exercises = it->second;
        std::ifstream in(c.scene_path, std::ios::binary);
        if (!in) throw BadUsage(c.scene_path.string() + ": cannot open: " + std::strerror(errno));
        try {
            c.scene = particlesim::read_scene(in, nullptr, boundary);
        } catch (const particlesim::InputError& e) {
            throw BadUsage(c.scene_path.string() + ":" + std::to_string(e.line()) + ": " + e.what());
        }
        cases.push_back(std::move(c));
    }
    if (cases.empty()) throw BadUsage(suite.string() + ": no *.in scenes");
    std::sort(cases.begin(), cases.end(), [](const SceneCase& a, const SceneCase& b) { return a.name < b.name; });
    return cases;
}

// The size io.md's output of this scene has, roughly: for the cap on output
// where the suite has no expected output.
std::int64_t estimated_output_bytes(const particlesim::Scene& scene) {
    const double blocks = scene.mode == particlesim::OutputMode::print ? static_cast<double>(scene.steps) + 1.0 : 2.0;
    return static_cast<std::int64_t>(std::min(blocks * static_cast<double>(scene.particle_count) * 96.0, 1e15));
}

struct Row {
    std::string verdict;  // io.md's words: conforms, shape, wrong, ...
    std::optional<std::int64_t> step;
    std::string message;
    std::vector<std::string> deviations;
    double seconds = 0.0;
    std::optional<double> reference_seconds;
    std::optional<int> exit_status;
    std::optional<int> signal;
    int left_running = 0;  // processes found running after the program ended (killed)
    int left_files = 0;    // entries it made in /tmp and the like (removed)
    int left_ipc = 0;      // System V IPC objects it left (removed)
};

std::string signal_name(int number) {
    const char* abbreviation = sigabbrev_np(number);
    return abbreviation ? "SIG" + std::string(abbreviation) : "signal " + std::to_string(number);
}

std::string first_line(const std::string& text) {
    const std::size_t end = text.find('\n');
    std::string line = text.substr(0, std::min<std::size_t>(end, 200));
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a line ended CR LF
    return line;
}

// The judgement of an output, in the grader's words.
void judge_into(Row& row, const SceneCase& c, const fs::path& output, const particlesim::StepCheckOptions& options) {
    std::FILE* file = std::fopen(output.c_str(), "rb");
    if (!file) throw std::runtime_error(output.string() + ": cannot read");
    std::fseek(file, 0, SEEK_END);
    const long size = std::ftell(file);
    std::rewind(file);
    if (size == 0) {
        std::fclose(file);
        row.verdict = "malformed";
        row.message = "the output is empty";
        return;
    }
    const Judgement j = judge_output(c.scene, file, "its output", options);
    std::fclose(file);
    row.deviations = j.deviations;
    switch (j.outcome) {
    case Outcome::conforms:
        row.verdict = "conforms";
        if (j.report.steps_judged < j.report.steps_checked) {  // the rest too chaotic to judge within rounding
            row.message = std::to_string(j.report.steps_judged) + " of the " + std::to_string(j.report.steps_checked) +
                          " steps judged";
        }
        break;
    case Outcome::shape:
        row.verdict = "shape";
        row.message = "the physics conforms; the shape deviates: " + j.deviations.front() +
                      (j.deviations.size() > 1 ? " (and " + std::to_string(j.deviations.size() - 1) + " more)" : "");
        break;
    case Outcome::wrong:
        row.verdict = "wrong";
        row.step = j.report.finding->step;
        row.message = "step " + std::to_string(j.report.finding->step) + ": " + j.report.finding->what;
        break;
    case Outcome::no_verdict: {
        row.verdict = "no-verdict";
        row.message = j.report.reason;
        // Within rounding the rules may go several ways; the reference's own bytes are one of them.
        if (c.expected_path) {
            std::ifstream a(output, std::ios::binary), b(*c.expected_path, std::ios::binary);
            const std::string mine((std::istreambuf_iterator<char>(a)), {});
            const std::string theirs((std::istreambuf_iterator<char>(b)), {});
            if (mine == theirs) {
                row.verdict = "conforms";
                row.message =
                    "byte-identical to the expected output (the rules alone give no verdict: " + j.report.reason + ")";
            }
        }
        break;
    }
    case Outcome::malformed:
        row.verdict = "malformed";
        row.message = j.message;
        break;
    }
}

Row grade_scene(const SceneCase& c, const Options& o, const std::optional<std::string>& reference,
                const fs::path& work) {
    Row row;
    SandboxLimits limits;
    limits.memory_bytes = o.memory_mb << 20;
    limits.processes = o.processes;
    limits.runs_alone = o.jobs == 1;
    limits.hidden = &o.hidden;
    limits.environment = &o.environment;
    const double expected_bytes = c.expected_path ? static_cast<double>(fs::file_size(*c.expected_path))
                                                  : static_cast<double>(estimated_output_bytes(c.scene));
    limits.output_bytes = static_cast<std::int64_t>(std::min(o.output_factor * expected_bytes + 1048576.0, 1e17));

    if (reference) {
        SandboxLimits generous = limits;
        generous.seconds = 3600.0;
        generous.memory_bytes = 0;  // simcli is trusted
        const SandboxRun ref = run_sandboxed({*reference, c.scene_path.string()}, "/dev/null",
                                             (work / (c.name + ".reference")).string(), generous);
        if (ref.end == SandboxRun::End::exited && ref.exit_status == 0) row.reference_seconds = ref.seconds;
        fs::remove(work / (c.name + ".reference"));
    }
    limits.seconds = o.timeout               ? *o.timeout
                     : row.reference_seconds ? std::max(10.0, 50.0 * *row.reference_seconds)
                                             : 60.0;

    std::vector<std::string> argv = o.program;
    bool path_argument = false;
    for (std::size_t k = 1; k < argv.size(); ++k) {
        if (argv[k] == "{}") {
            argv[k] = c.scene_path.string();
            path_argument = true;
        }
    }
    const fs::path output = work / (c.name + ".out");
    const SandboxRun run =
        run_sandboxed(argv, path_argument ? "/dev/null" : c.scene_path.string(), output.string(), limits);
    row.seconds = run.seconds;
    // Shown on the grader's terminal and in the reports: no escape sequence of the program's passes.
    const std::string stderr_line = particlesim::printable_text(first_line(run.stderr_head));
    switch (run.end) {
    case SandboxRun::End::timeout: {
        char text[64];
        std::snprintf(text, sizeof text, "%g", limits.seconds);
        row.verdict = "timeout";
        row.message = "stopped after " + std::string(text) + " s (--timeout)";
        break;
    }
    case SandboxRun::End::output_limit:
        row.verdict = "output-limit";
        row.message =
            "stopped after writing more than " + std::to_string(limits.output_bytes) + " bytes (--output-factor)";
        break;
    case SandboxRun::End::files_limit:
        row.verdict = "output-limit";
        if (run.files_too_deep) {
            row.message = "stopped when it nested directories more than " + std::to_string(max_files_depth) +
                          " deep, deeper than its files are measured";
            break;
        }
        row.message = "stopped when its files together held " + std::to_string(run.files_bytes) +
                      " bytes, more than the largest file it may write (" + std::to_string(run.files_limit) +
                      "; counted: " +
                      (runs_programs_as_own_users() ? "its directory, /tmp, /var/tmp, /dev/shm" : "its directory") +
                      " and the files it held open that no directory names)";
        break;
    case SandboxRun::End::memory_limit:
        // Killed, as the kernel's out-of-memory killer would have: a crash, named.
        row.verdict = "crashed";
        row.signal = SIGKILL;
        row.message = "stopped when its processes together held " + std::to_string(run.memory_bytes) +
                      " bytes of memory, more than --memory (" + std::to_string(run.memory_limit) +
                      "; counted: their private resident memory and what waited in their pipes and sockets" +
                      (runs_programs_as_own_users() && !runs_programs_isolated()
                           ? ", and its System V shared memory and message queues)"
                           : ")");
        break;
    case SandboxRun::End::signalled:
        row.verdict = "crashed";
        row.signal = run.signal;
        row.message = "killed by " + signal_name(run.signal) + (stderr_line.empty() ? "" : ": " + stderr_line);
        break;
    case SandboxRun::End::exited:
        row.exit_status = run.exit_status;
        judge_into(row, c, output, o.check);
        if (run.exit_status != 0) {
            row.message = "exit status " + std::to_string(run.exit_status) + " after an output judged " + row.verdict +
                          (row.message.empty() ? "" : " (" + row.message + ")") +
                          (stderr_line.empty() ? "" : "; stderr: " + stderr_line);
            row.verdict = "exit-status";
        }
        break;
    }
    row.left_running = run.left_running;
    row.left_files = run.left_files;
    row.left_ipc = run.left_ipc;
    // "it left 2 files in ...", after what the message says already.
    const auto tell_left = [&](int count, const std::string& one, const std::string& many, const std::string& rest) {
        if (count == 0) return;
        const std::string left = "it left " + std::to_string(count) + " " + (count == 1 ? one : many) + " " + rest;
        row.message = row.message.empty() ? left : row.message + "; " + left;
    };
    tell_left(run.left_files, "file", "files", "in /tmp, /var/tmp or /dev/shm (removed)");
    tell_left(run.left_running, "process", "processes", "running after it ended (killed)");
    tell_left(run.left_ipc, "System V IPC object", "System V IPC objects",
              "(shared memory, semaphores, queues; removed)");
    if (!o.outputs_dir.empty()) {
        std::error_code ignored;
        fs::copy_file(output, fs::path(o.outputs_dir) / (c.name + ".out"), fs::copy_options::overwrite_existing,
                      ignored);
    }
    fs::remove(output);
    return row;
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", seconds);
    return text;
}

std::string ratio_text(const Row& row) {
    if (!row.reference_seconds || *row.reference_seconds <= 0.0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", row.seconds / *row.reference_seconds);
    return text;
}

std::string program_text(const Options& o) {
    std::string text;
    for (const std::string& a : o.program) text += (text.empty() ? "" : " ") + a;
    return text;
}

std::string header_text(const Options& o, std::size_t scenes, int conforming) {
    // No more ran at once than there are scenes.
    const std::size_t side_by_side = std::min(static_cast<std::size_t>(o.jobs), scenes);
    return "simcheck grade: " + o.program_text + " on " + o.suite.string() + ": " + std::to_string(conforming) +
           " of " + std::to_string(scenes) + " scenes conform" +
           (side_by_side > 1
                ? " (" + std::to_string(side_by_side) + " scenes ran side by side: times are shared-machine times)"
                : "");
}

void write_text(std::FILE* out, const Options& o, const std::vector<SceneCase>& cases, const std::vector<Row>& rows,
                int conforming) {
    std::fprintf(out, "%s\n\n", header_text(o, cases.size(), conforming).c_str());
    std::size_t width = 5;
    for (const SceneCase& c : cases) width = std::max(width, c.name.size());
    std::fprintf(out, "%-*s  %-12s  %5s  %8s  %8s  %s\n", static_cast<int>(width), "scene", "verdict", "step",
                 "seconds", "x simcli", "exercises");
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        std::string exercises = cases[k].exercises;
        if (exercises.size() > 60) exercises = exercises.substr(0, 57) + "...";
        std::fprintf(out, "%-*s  %-12s  %5s  %8s  %8s  %s\n", static_cast<int>(width), cases[k].name.c_str(),
                     r.verdict.c_str(), r.step ? std::to_string(*r.step).c_str() : "-", seconds_text(r.seconds).c_str(),
                     ratio_text(r).c_str(), exercises.c_str());
    }
    bool any = false;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        if (r.message.empty() && r.deviations.empty()) continue;
        if (!any) std::fputc('\n', out);
        any = true;
        std::fprintf(out, "%s: %s: %s\n", cases[k].name.c_str(), r.verdict.c_str(), r.message.c_str());
        if (r.deviations.size() > 1 || (r.verdict != "shape" && !r.deviations.empty())) {
            for (const std::string& d : r.deviations) std::fprintf(out, "    - %s\n", d.c_str());
        }
    }
}

std::string markdown_cell(std::string text) {
    std::string out;
    for (const char c : text) {
        if (c == '|') {
            out += "\\|";
        } else if (c == '\n') {
            out += ' ';
        } else {
            out += c;
        }
    }
    return out;
}

void write_markdown(std::FILE* out, const Options& o, const std::vector<SceneCase>& cases, const std::vector<Row>& rows,
                    int conforming) {
    std::fprintf(out, "## %s\n\n", markdown_cell(header_text(o, cases.size(), conforming)).c_str());
    std::fprintf(
        out, "| scene | exercises | verdict | first wrong step | seconds | x simcli |\n|---|---|---|---|---|---|\n");
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        std::fprintf(out, "| %s | %s | %s | %s | %s | %s |\n", markdown_cell(cases[k].name).c_str(),
                     markdown_cell(cases[k].exercises).c_str(), r.verdict.c_str(),
                     r.step ? std::to_string(*r.step).c_str() : "", seconds_text(r.seconds).c_str(),
                     ratio_text(r).c_str());
    }
    std::fputc('\n', out);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        if (r.message.empty() && r.deviations.empty()) continue;
        std::fprintf(out, "- **%s** (%s): %s\n", markdown_cell(cases[k].name).c_str(), r.verdict.c_str(),
                     markdown_cell(r.message).c_str());
        for (const std::string& d : r.deviations) std::fprintf(out, "  - %s\n", markdown_cell(d).c_str());
    }
}

void write_json(std::FILE* out, const Options& o, const std::vector<SceneCase>& cases, const std::vector<Row>& rows) {
    const auto optional_number = [](const auto& value) { return value ? std::to_string(*value) : std::string("null"); };
    const auto seconds_json = [](double seconds) {
        char text[40];
        std::snprintf(text, sizeof text, "%.6f", seconds);
        return std::string(text);
    };
    std::string json = "{\"program\": " + json_string(o.program_text) +
                       ", \"suite\": " + json_string(o.suite.string()) + ", \"jobs\": " + std::to_string(o.jobs) +
                       ", \"own_users\": " + (runs_programs_as_own_users() ? "true" : "false") +
                       ", \"isolated\": " + (runs_programs_isolated() ? "true" : "false") +
                       ", \"read_only\": " + (runs_programs_read_only() ? "true" : "false") +
                       ", \"signals_confined\": " + (runs_programs_with_signals_confined() ? "true" : "false") +
                       ", \"processes_hidden\": " + (runs_programs_with_own_processes() ? "true" : "false") +
                       ", \"scenes\": [";
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const Row& r = rows[k];
        json += k > 0 ? ",\n  " : "\n  ";
        json += "{\"scene\": " + json_string(cases[k].name) + ", \"exercises\": " + json_string(cases[k].exercises);
        json += ", \"verdict\": " + json_string(r.verdict) + ", \"step\": " + optional_number(r.step);
        json += ", \"message\": " + json_string(r.message) + ", \"seconds\": " + seconds_json(r.seconds);
        json += ", \"reference_seconds\": " + (r.reference_seconds ? seconds_json(*r.reference_seconds) : "null");
        json += ", \"exit_status\": " + optional_number(r.exit_status) + ", \"signal\": " + optional_number(r.signal);
        json += ", \"left_running\": " + std::to_string(r.left_running);
        json += ", \"left_files\": " + std::to_string(r.left_files);
        json += ", \"left_ipc\": " + std::to_string(r.left_ipc);
        json += ", \"deviations\": [";
        for (std::size_t d = 0; d < r.deviations.size(); ++d)
            json += (d > 0 ? ", " : "") + json_string(r.deviations[d]);
        json += "]}";
    }
    json += "\n]}\n";
    std::fputs(json.c_str(), out);
}

// Opens `path` for writing as the report will (making it, then removing what
// it made), so that an unwritable report is refused before any program runs.
void require_can_write(const std::string& option, const std::string& path) {
    std::error_code error;
    if (fs::is_directory(path, error)) throw BadUsage(option + " " + path + ": is a directory");
    const bool existed = fs::exists(path, error);
    std::FILE* file = std::fopen(path.c_str(), "ab");
    if (!file) throw BadUsage(option + " " + path + ": cannot write: " + std::strerror(errno));
    std::fclose(file);
    if (!existed) std::remove(path.c_str());
}

// Writes one report after the grade; a failure (a full disk) is said on
// stderr, naming the option, and the other report is still written.
bool write_report_file(const std::string& option, const std::string& path,
                       const std::function<void(std::FILE*)>& write) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    bool written = file != nullptr;
    if (file) {
        write(file);
        written = std::fflush(file) == 0 && !std::ferror(file);
        written = std::fclose(file) == 0 && written;
    }
    if (!written) {
        std::fprintf(stderr, "simcheck grade: %s %s: cannot write: %s (the grade is done: its summary is on stdout)\n",
                     option.c_str(), path.c_str(), std::strerror(errno));
    }
    return written;
}

}  // namespace

int grade_main(int argc, char** argv) {
    // Ctrl-C, a batch system's stop or a closed terminal: the runs are stopped and cleaned up first.
    struct sigaction on_signal {};
    on_signal.sa_handler = [](int signal) { interrupt_runs(signal); };
    sigemptyset(&on_signal.sa_mask);
    on_signal.sa_flags = SA_RESTART;  // poll() still returns at once; the rest goes on
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &on_signal, nullptr);
    try {
        const std::optional<Options> parsed = parse(argc, argv);
        if (!parsed) return 0;
        Options o = *parsed;
        const std::optional<std::string> program = find_program(o.program.front());
        if (!program) throw BadUsage(o.program.front() + ": no such program (or not executable)");
        // It runs in a directory of its own: a relative path would not reach it there.
        o.program_text = program_text(o);
        o.program.front() = fs::absolute(*program).lexically_normal().string();
        if (runs_programs_as_own_users() && kept_capability() == CAP_DAC_READ_SEARCH) {
            // It runs as a user of its own, for whom only the bits for others hold.
            struct stat info {};
            if (stat(o.program.front().c_str(), &info) != 0 || (info.st_mode & S_IXOTH) == 0)
                throw BadUsage(o.program.front() +
                               ": not executable by other users, and run by root simcheck grade runs each program "
                               "as a user of its own (chmod o+x it)");
        } else if (geteuid() == 0) {
            std::fprintf(stderr,
                         "simcheck grade: warning: run by root but unable to run programs as users of their own "
                         "(no CAP_SETUID, CAP_SETGID or CAP_CHOWN, neither CAP_DAC_READ_SEARCH nor "
                         "CAP_DAC_OVERRIDE, or no unused user ids mapped): --processes does not hold, and the "
                         "programs run as root\n");
        }
        if (!o.outputs_dir.empty()) {
            std::error_code error;
            if (fs::equivalent(o.outputs_dir, o.suite, error))
                throw BadUsage("--outputs " + o.outputs_dir +
                               " is the suite: the outputs, NAME.out, would replace its expected outputs");
            fs::create_directories(o.outputs_dir, error);
            if (error) throw BadUsage("--outputs " + o.outputs_dir + ": cannot make the directory: " + error.message());
        }
        // A report that cannot be written fails now, not after the runs.
        if (!o.json_path.empty()) require_can_write("--json", o.json_path);
        if (!o.markdown_path.empty()) require_can_write("--markdown", o.markdown_path);
        const std::vector<SceneCase> cases = read_suite(o.suite, o.check.boundary);
        const std::optional<std::string> reference = find_reference(o);

        std::string work_template = (fs::temp_directory_path() / "simcheck-outputs-XXXXXX").string();
        if (!mkdtemp(work_template.data())) throw std::runtime_error("cannot make a directory for the outputs");
        const fs::path work = work_template;
        std::vector<std::string> hidden{work.string()};
        for (const SceneCase& c : cases) {
            if (c.expected_path) hidden.push_back(c.expected_path->string());
        }
        // --outputs DIR is hidden unless the scenes, the program or the runs' directories lie in it.
        if (!o.outputs_dir.empty() && !lies_within(o.suite, o.outputs_dir) &&
            !lies_within(o.program.front(), o.outputs_dir) && !lies_within(work.parent_path(), o.outputs_dir))
            hidden.push_back(o.outputs_dir);
        // What only its owner may read in /etc and the homes: the program, the suite, the reference and the
        // runs' directories stay.
        std::vector<std::string> needed{o.program.front(), o.suite.string(), work.string(),
                                        fs::temp_directory_path().string()};
        if (reference) needed.push_back(*reference);
        if (!o.outputs_dir.empty()) needed.push_back(o.outputs_dir);
        for (const std::string& path : private_entries(needed)) hidden.push_back(path);
        // The suite stays read-only where it lies in /tmp: the next grade reads it.
        o.hidden = HiddenPaths(hidden, {o.suite.string()});
        if (!runs_programs_isolated()) {
            std::fprintf(stderr,
                         "simcheck grade: warning: unable to make namespaces (%s): the programs can read the "
                         "expected outputs and reach the network%s\n",
                         namespaces_refused_because().c_str(),
                         geteuid() == 0 ? "" : "; grade as root, or see docs/checking.md");
        }
        if (!runs_programs_read_only()) {
            std::fprintf(stderr,
                         "simcheck grade: warning: unable to make files read-only (Landlock needs Linux 6.2, "
                         "mount_setattr in namespaces 5.12): the programs can write wherever %s\n",
                         geteuid() == 0 ? "any user may" : "this user may");
        }
        if (!runs_programs_with_signals_confined() && !runs_programs_as_own_users()) {
            std::fprintf(stderr,
                         "simcheck grade: warning: unable to confine the programs' signals (neither a PID "
                         "namespace nor Landlock's signal scope, Linux 6.12): they can signal every process of "
                         "this user\n");
        }
        std::vector<Row> rows(cases.size());
        std::atomic<std::size_t> next{0};
        std::string failure;
        std::mutex failure_lock;
        const auto worker = [&] {
            for (std::size_t k; runs_interrupted() == 0 && (k = next.fetch_add(1)) < cases.size();) {
                try {
                    rows[k] = grade_scene(cases[k], o, reference, work);
                } catch (const SandboxInterrupted&) {
                    break;
                } catch (const std::exception& e) {
                    const std::lock_guard<std::mutex> lock(failure_lock);
                    failure = cases[k].name + ": " + apps_common::without_library_names(e.what());
                }
            }
        };
        std::vector<std::thread> threads;
        for (int t = 1; t < std::min<int>(o.jobs, static_cast<int>(cases.size())); ++t) threads.emplace_back(worker);
        worker();
        for (std::thread& t : threads) t.join();
        std::error_code ignored;
        fs::remove_all(work, ignored);
        if (const int signal = runs_interrupted(); signal != 0) {
            std::fprintf(stderr,
                         "simcheck grade: interrupted (%s): the programs running were stopped and nothing of "
                         "them is left; no report\n",
                         strsignal(signal));
            // Ended by the signal, as the shell and a batch system expect.
            std::signal(signal, SIG_DFL);
            std::raise(signal);
            return 128 + signal;
        }
        if (!failure.empty()) throw std::runtime_error(failure);

        const int conforming = static_cast<int>(
            std::count_if(rows.begin(), rows.end(), [](const Row& r) { return r.verdict == "conforms"; }));
        write_text(stdout, o, cases, rows, conforming);
        bool reports_written = true;
        if (!o.json_path.empty()) {
            reports_written =
                write_report_file("--json", o.json_path, [&](std::FILE* f) { write_json(f, o, cases, rows); }) &&
                reports_written;
        }
        if (!o.markdown_path.empty()) {
            reports_written = write_report_file("--markdown", o.markdown_path,
                                                [&](std::FILE* f) { write_markdown(f, o, cases, rows, conforming); }) &&
                              reports_written;
        }
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
            std::fprintf(stderr, "simcheck grade: cannot write the summary to stdout: %s (the reports are written)\n",
                         std::strerror(errno));
            return 2;
        }
        if (!reports_written) return 2;
        return conforming == static_cast<int>(rows.size()) ? 0 : 1;
    } catch (const BadUsage& e) {
        std::fprintf(stderr, "simcheck grade: %s\n", apps_common::without_library_names(e.what()).c_str());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "simcheck grade: %s\n", apps_common::without_library_names(e.what()).c_str());
        return 2;
    }
}

}  // namespace simcheck
