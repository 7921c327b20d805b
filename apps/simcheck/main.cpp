// simcheck: checks any program's output against the rules (io.md "simcheck",
// docs/checking.md). Thin by design: arguments -> scene -> output reader ->
// the library's step checker -> report.
//   exit 0: conforms; 1: breaks the rules (first line "step N: ...");
//   2: bad usage or an unreadable scene or output; 3: no verdict possible.

#include "output_check.hpp"
#include "particlesim/output_reader.hpp"
#include "report.hpp"

#include "particlesim/scene.hpp"
#include "particlesim/step_check.hpp"
#include "particlesim/version.hpp"

#include <charconv>
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

constexpr const char* usage = R"(usage: simcheck SCENE OUTPUT [--substeps K | --engine exact] [--json]

Checks OUTPUT, written by any program for SCENE in the format of io.md,
against the rules: each printed step from the program's own previous printed
step, within the uncertainty of 8-decimal printing (docs/checking.md).

  SCENE, OUTPUT          files; one of them may be '-' (stdin)
      --substeps K       the output was made with K micro-steps per step
      --engine step|exact  exact: check against continuous-time hard disks
      --json             the report as one JSON object
  -h, --help             this text, exit 0
      --version          the version, exit 0

exit status: 0 conforms; 1 breaks the rules (the report's first line is
"step N: ..."); 2 bad usage or an unreadable scene or output; 3 no verdict
(a perf-mode output whose run may go several ways within rounding, ...).
)";

class BadUsage : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

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
        const auto value = [&]() -> std::string {
            if (k + 1 >= argc) throw BadUsage(arg + " needs a value");
            return argv[++k];
        };
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
        } else if (arg == "--substeps") {
            const std::string text = value();
            int substeps = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), substeps);
            if (error != std::errc() || end != text.data() + text.size() || substeps < 1 || substeps > 1000000) {
                throw BadUsage("--substeps needs a whole number from 1 to 1000000, not \"" + text + "\"");
            }
            args.options.substeps = substeps;
            substeps_given = true;
        } else if (arg == "--engine") {
            const std::string text = value();
            if (text == "exact") {
                args.options.rules = CheckedRules::exact;
            } else if (text != "step") {
                throw BadUsage("--engine is step or exact, not \"" + text + "\"");
            }
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw BadUsage("unknown option " + arg + " (simcheck --help lists them)");
        } else {
            files.push_back(arg);
        }
    }
    if (files.size() != 2) throw BadUsage("needs a SCENE and an OUTPUT (simcheck --help)");
    if (files[0] == "-" && files[1] == "-") throw BadUsage("SCENE and OUTPUT cannot both be stdin");
    if (substeps_given && args.options.rules == CheckedRules::exact) {
        throw BadUsage("--substeps belongs to the step rules; the exact engine has none");
    }
    args.scene_path = files[0];
    args.output_path = files[1];
    return args;
}

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

Scene read_scene_file(const std::string& path) {
    const std::string name = display_name(path);
    try {
        if (path == "-") return read_scene(std::cin);
        std::ifstream file(path, std::ios::binary);
        if (!file) throw BadUsage(name + ": cannot open: " + std::strerror(errno));
        return read_scene(file);
    } catch (const InputError& e) {
        throw BadUsage(name + ":" + std::to_string(e.line()) + ": " + e.what());
    }
}

std::string rules_name(const StepCheckOptions& options) {
    if (options.rules == CheckedRules::exact) return "continuous-time hard disks";
    if (options.substeps == 1) return "the step rules";
    return "the step rules with " + std::to_string(options.substeps) + " substeps";
}

int run(const Arguments& args) {
    const Scene scene = read_scene_file(args.scene_path);
    const std::string output_name = display_name(args.output_path);
    std::FILE* file = args.output_path == "-" ? stdin : std::fopen(args.output_path.c_str(), "rb");
    if (!file) throw BadUsage(output_name + ": cannot open: " + std::strerror(errno));
    particlesim::OutputReader reader(file, output_name);
    Report report;
    try {
        report = check_output(scene, reader, args.options);
    } catch (const InputError& e) {
        if (file != stdin) std::fclose(file);
        throw BadUsage(output_name + ":" + std::to_string(e.line()) + ": " + e.what());
    } catch (const std::exception& e) {
        // The rules cannot be applied here (the exact engine refuses the
        // printed state, a step needs millions of events, ...).
        report.verdict = Verdict::no_verdict;
        report.reason = e.what();
    }
    if (file != stdin) std::fclose(file);
    const ReportContext context{output_name, rules_name(args.options)};
    if (args.json) {
        write_json_report(stdout, report, context);
    } else {
        write_text_report(stdout, report, context);
    }
    if (std::fflush(stdout) != 0) return exit_bad_input;
    switch (report.verdict) {
    case Verdict::conforms: return exit_conforms;
    case Verdict::breaks_rules: return exit_breaks_rules;
    case Verdict::no_verdict: return exit_no_verdict;
    }
    return exit_no_verdict;
}

}  // namespace

int main(int argc, char** argv) {
    bool json = false;
    for (int k = 1; k < argc; ++k) json = json || std::strcmp(argv[k], "--json") == 0;
    try {
        const std::optional<Arguments> args = parse_arguments(argc, argv);
        if (!args) return exit_conforms;
        return run(*args);
    } catch (const BadUsage& e) {
        if (json) write_json_unreadable(stdout, e.what());
        std::fprintf(stderr, "simcheck: %s\n", e.what());
        return exit_bad_input;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "simcheck: %s\n", e.what());
        return exit_bad_input;
    }
}
