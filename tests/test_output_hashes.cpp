// The output of simcli, byte for byte, on every example and a few hundred
// random scenes, under both engines, every pair search and several thread
// counts, compared with hashes recorded before the library's API was
// reshaped (expected_output_hashes.hpp). A refactoring must not change one
// byte. `--generate` prints the table for the simcli it is given, so the
// table can be rebuilt from a trusted build.

#include "check.hpp"
#include "expected_output_hashes.hpp"
#include "run_process.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Case {
    std::string name;
    std::vector<std::string> args;
    std::string input;
};

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h = 14695981039346656037ULL) {
    for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
    return h;
}

// A fixed generator of the test's own, so the cases never change with the library.
struct CaseRandom {
    std::uint64_t state;
    std::uint64_t next() {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return state >> 33;
    }
    std::uint64_t below(std::uint64_t n) { return next() % n; }
};

std::string format_double(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::vector<Case> all_cases() {
    const std::string examples = PARTICLESIM_EXAMPLES_DIR;
    const char* example_names[] = {"corner",  "crossing",       "default", "faster_than_box", "glancing_line",
                                   "head_on", "newtons_cradle", "square",  "triangle",        "wall_then_pair"};
    const std::vector<std::vector<std::string>> step_settings = {
        {"--broadphase", "brute", "-t", "1"}, {"--broadphase", "grid", "-t", "1"}, {"--broadphase", "grid", "-t", "2"},
        {"--grid", "4", "-t", "2"},           {"--substeps", "3", "-t", "2"},      {"--engine", "exact"}};
    std::vector<Case> cases;
    for (const char* example : example_names) {
        const bool is_default = std::strcmp(example, "default") == 0;
        for (const std::vector<std::string>& setting : step_settings) {
            // The default scene costs most: brute force and substeps add nothing the others miss.
            if (is_default && (setting[1] == "brute" || setting[1] == "3")) continue;
            Case c{std::string(example), setting, ""};
            c.args.push_back(examples + "/" + example + ".in");
            for (const std::string& a : setting) c.name += " " + a;
            cases.push_back(std::move(c));
        }
    }
    // Random scenes (io.md: header only, drawn from --seed): small boxes so
    // that the default speeds (up to L/4 per step) keep the exact engine busy
    // but finite, area fractions from dilute to crowded.
    CaseRandom random{20261122};
    const double fractions[] = {0.005, 0.02, 0.08, 0.2, 0.35};
    const double boxes[] = {40.0, 100.0, 250.0, 1000.0};
    for (int k = 0; k < 300; ++k) {
        const std::uint64_t count = 1 + random.below(k < 240 ? 60 : 400);
        const double box = boxes[random.below(4)];
        const double fraction = fractions[random.below(5)];
        double radius = box * std::sqrt(fraction / (3.141592653589793 * static_cast<double>(count)));
        if (2.0 * radius > box) radius = box / 2.0;
        const std::uint64_t steps = 1 + random.below(k < 240 ? 25 : 8);
        const bool print = random.below(3) != 0;
        const std::string input = std::to_string(count) + "\n" + format_double(box) + "\n" + format_double(radius) +
                                  "\n" + std::to_string(steps) + "\n" + (print ? "print\n" : "perf\n");
        const std::string seed = std::to_string(1000 + k);
        const std::vector<std::vector<std::string>> settings = {
            {"--broadphase", "brute", "-t", "1"},
            {"--broadphase", "grid", "-t", std::to_string(1 + k % 2)},
            {"--substeps", std::to_string(2 + k % 3), "-t", "2"},
            {"--engine", "exact"}};
        for (const std::vector<std::string>& setting : settings) {
            Case c{"random " + std::to_string(k) + " (N " + std::to_string(count) + ", L " + format_double(box) +
                       ", r " + format_double(radius) + ", S " + std::to_string(steps) + ")",
                   setting, input};
            for (const std::string& a : setting) c.name += " " + a;
            c.args.push_back("--seed");
            c.args.push_back(seed);
            cases.push_back(std::move(c));
        }
    }
    // Large enough to be stored in position order (from 65536 particles).
    for (const char* threads : {"1", "2"}) {
        cases.push_back({std::string("random 70000 sorted by position -t ") + threads,
                         {"-t", threads, "--seed", "7"},
                         "70000\n40000\n1\n3\nperf\n"});
    }
    return cases;
}

std::uint64_t output_hash(const std::string& simcli, const Case& c) {
    const run_process::Result result = run_process::run(simcli, c.args, c.input);
    return fnv1a(result.out, fnv1a(std::to_string(result.status)));
}

}  // namespace

int main(int argc, char** argv) {
    const bool generate = argc > 1 && std::strcmp(argv[1], "--generate") == 0;
    const std::string simcli = generate && argc > 2 ? argv[2] : SIMCLI_PATH;
    const std::vector<Case> cases = all_cases();
    if (generate) {
        for (const Case& c : cases)
            std::printf("    0x%016" PRIx64 "ULL,  // %s\n", output_hash(simcli, c), c.name.c_str());
        return 0;
    }
    return check::run(argc, argv, "test_output_hashes",
                      {{"simcli output unchanged", [&] {
                            CHECK_EQ(cases.size(), std::size(expected_output_hashes));
                            for (std::size_t k = 0; k < cases.size() && k < std::size(expected_output_hashes); ++k) {
                                const check::Context context("running simcli on ", cases[k].name);
                                CHECK_EQ(output_hash(simcli, cases[k]), expected_output_hashes[k]);
                            }
                        }}});
}
