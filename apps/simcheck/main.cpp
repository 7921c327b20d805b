// simcheck: checks any program's output against the rules (io.md "simcheck",
// docs/checking.md), or grades a program on a suite (`simcheck grade`,
// grade.hpp). Thin by design: arguments -> scene -> judge -> report.
//   exit 0: conforms; 1: breaks the rules (first line "step N: ...");
//   2: bad usage or an unreadable scene or output; 3: no verdict possible;
//   4: the physics conforms, the output's shape deviates (named).

#include "command_line.hpp"
#include "common/input_path.hpp"
#include "common/library_message.hpp"
#include "common/standard_streams.hpp"
#include "grade.hpp"
#include "judge.hpp"
#include "report.hpp"

#include "particlesim/scene.hpp"
#include "particlesim/step_check.hpp"
#include "particlesim/version.hpp"

#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace particlesim;
using namespace simcheck;

constexpr int exit_conforms = 0;
constexpr int exit_breaks_rules = 1;
constexpr int exit_bad_input = 2;
constexpr int exit_no_verdict = 3;
constexpr int exit_shape = 4;

constexpr const char* usage =
    R"(usage: simcheck SCENE OUTPUT [--substeps K | --engine exact [--boundary periodic]] [--json]
       simcheck grade SUITE_DIR [OPTIONS] -- PROGRAM [ARGS...]   (simcheck grade --help)

Checks OUTPUT, written by any program for SCENE in the format of io.md,
against the rules: each printed step from the program's own previous printed
step, within the uncertainty of 8-decimal printing (docs/checking.md).

  SCENE, OUTPUT          files; one of them may be '-' (stdin)
      --substeps K       the output was made with K micro-steps per step
      --engine step|exact  exact: check against continuous-time hard disks
      --boundary walls|periodic  periodic: the exact rules in a periodic box
      --json             the report as one JSON object
  -h, --help             this text, exit 0
      --version          the version, exit 0

exit status: 0 conforms; 1 breaks the rules (the report's first line is
"step N: ..."); 2 bad usage or an unreadable scene or output; 3 no verdict
(a perf-mode output whose run may go several ways within rounding, ...);
4 the physics conforms but the output's shape deviates from io.md's (a
block printed twice, no counters on the final block, no step-0 block,
numbers not in %.8f, trailing spaces or blank lines: named in the report).
)";

struct Arguments {
    std::string scene_path;
    std::string output_path;
    StepCheckOptions options;
    bool json = false;
};

std::optional<Arguments> parse_arguments(int argc, char** argv) {
    Arguments args;
    std::vector<std::string> files;
    bool substeps_given = false;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        const auto value = [&] { return option_value(argc, argv, k); };
        if (arg == "-h" || arg == "--help") {
            std::fputs(usage, stdout);
            return std::nullopt;
        }
        if (arg == "--version") {
            std::printf("simcheck %s\n", particlesim::version);
            return std::nullopt;
        }
        if (arg == "--json") {
            args.json = true;
        } else if (read_rules_option(arg, value, args.options)) {
            substeps_given = substeps_given || arg == "--substeps";
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw BadUsage("unknown option " + arg + " (simcheck --help lists them)");
        } else {
            files.push_back(arg);
        }
    }
    if (files.size() > 2) {
        throw BadUsage("takes a SCENE and an OUTPUT, and \"" + files[2] + "\" would be a third (simcheck --help)");
    }
    if (files.size() != 2) throw BadUsage("needs a SCENE and an OUTPUT (simcheck --help)");
    if (files[0] == "-" && files[1] == "-") throw BadUsage("SCENE and OUTPUT cannot both be stdin");
    require_consistent_rules(args.options, substeps_given);
    args.scene_path = files[0];
    args.output_path = files[1];
    return args;
}

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

void refuse_directory(const std::string& path, const std::string& name) {
    if (apps_common::names_a_directory(path)) throw BadUsage(name + ": is a directory");
}

Scene read_scene_file(const std::string& path, Boundary boundary) {
    const std::string name = display_name(path);
    refuse_directory(path, name);
    try {
        if (path == "-") return read_scene(std::cin, nullptr, boundary);
        std::ifstream file(path, std::ios::binary);
        if (!file) throw BadUsage(name + ": cannot open: " + std::strerror(errno));
        return read_scene(file, nullptr, boundary);
    } catch (const InputError& e) {
        throw BadUsage(name + ":" + std::to_string(e.line()) + ": " + e.what());
    }
}

std::string rules_name(const StepCheckOptions& options) {
    if (options.rules == CheckedRules::exact) {
        return options.boundary == Boundary::periodic ? "continuous-time hard disks in a periodic box"
                                                      : "continuous-time hard disks";
    }
    if (options.substeps == 1) return "the step rules";
    return "the step rules with " + std::to_string(options.substeps) + " substeps";
}

// Standard input read on from where a copy of its first bytes ends: the
// copy first, then the rest as it comes. A stream that can be read once.
struct CopyThenRest {
    std::FILE* copy;
    bool copy_done = false;
};

ssize_t read_copy_then_rest(void* cookie, char* buffer, std::size_t size) {
    auto* source = static_cast<CopyThenRest*>(cookie);
    if (!source->copy_done) {
        const std::size_t got = std::fread(buffer, 1, size, source->copy);
        if (got > 0) return static_cast<ssize_t>(got);
        source->copy_done = true;
    }
    const std::size_t got = std::fread(buffer, 1, size, stdin);
    return got > 0 || !std::ferror(stdin) ? static_cast<ssize_t>(got) : -1;
}

int close_copy_then_rest(void* cookie) {
    auto* source = static_cast<CopyThenRest*>(cookie);
    std::fclose(source->copy);
    delete source;
    return 0;
}

// The output as a file. From stdin, what fits the shape reader's reach is
// copied first, so that it can be read twice (for its shape, then
// strictly); a longer output is read once, strictly, as it comes, so that
// an endless or huge stream is judged from its first lines instead of being
// stored whole first.
std::FILE* open_output(const std::string& path, const std::string& name) {
    refuse_directory(path, name);
    if (path != "-") {
        std::FILE* file = std::fopen(path.c_str(), "rb");
        if (!file) throw BadUsage(name + ": cannot open: " + std::strerror(errno));
        return file;
    }
    std::FILE* copy = std::tmpfile();
    if (!copy) throw BadUsage(name + ": cannot keep a copy: " + std::strerror(errno));
    char buffer[1 << 16];
    std::int64_t copied = 0;
    for (std::size_t got; copied <= largest_shaped_output && (got = std::fread(buffer, 1, sizeof buffer, stdin)) > 0;) {
        if (std::fwrite(buffer, 1, got, copy) != got) {
            std::fclose(copy);
            throw BadUsage(name + ": cannot keep a copy: " + std::strerror(errno));
        }
        copied += static_cast<std::int64_t>(got);
    }
    std::rewind(copy);
    if (copied <= largest_shaped_output) return copy;
    auto* source = new CopyThenRest{copy};
    std::FILE* stream =
        fopencookie(source, "rb", cookie_io_functions_t{read_copy_then_rest, nullptr, nullptr, close_copy_then_rest});
    if (!stream) {
        close_copy_then_rest(source);
        throw BadUsage(name + ": cannot read on: " + std::strerror(errno));
    }
    return stream;
}

int run(const Arguments& args) {
    const Scene scene = read_scene_file(args.scene_path, args.options.boundary);
    const std::string output_name = display_name(args.output_path);
    std::FILE* file = open_output(args.output_path, output_name);
    const Judgement judgement = judge_output(scene, file, output_name, args.options);
    std::fclose(file);
    if (judgement.outcome == Outcome::malformed) throw BadUsage(judgement.message);
    const ReportContext context{output_name, rules_name(args.options)};
    if (args.json) {
        write_json_report(stdout, judgement, context);
    } else {
        write_text_report(stdout, judgement, context);
    }
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "simcheck: cannot write the report: %s\n", std::strerror(errno));
        return exit_bad_input;
    }
    switch (judgement.outcome) {
    case Outcome::conforms: return exit_conforms;
    case Outcome::shape: return exit_shape;
    case Outcome::wrong: return exit_breaks_rules;
    case Outcome::no_verdict: return exit_no_verdict;
    case Outcome::malformed: return exit_bad_input;
    }
    return exit_no_verdict;
}

}  // namespace

int main(int argc, char** argv) {
    // A run's pipes must not take the numbers of closed standard streams.
    if (!apps_common::open_closed_standard_streams()) return exit_bad_input;
    if (argc > 1 && std::strcmp(argv[1], "grade") == 0) return simcheck::grade_main(argc - 1, argv + 1);
    bool json = false;
    for (int k = 1; k < argc; ++k) json = json || std::strcmp(argv[k], "--json") == 0;
    try {
        const std::optional<Arguments> args = parse_arguments(argc, argv);
        if (!args) return exit_conforms;
        return run(*args);
    } catch (const BadUsage& e) {
        if (json) write_json_unreadable(stdout, apps_common::without_library_names(e.what()));
        std::fprintf(stderr, "simcheck: %s\n", apps_common::without_library_names(e.what()).c_str());
        return exit_bad_input;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "simcheck: %s\n", apps_common::without_library_names(e.what()).c_str());
        return exit_bad_input;
    }
}
