#include "suite.hpp"

#include "whole_file.hpp"

#include "particlesim/particlesim.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace simgen {

namespace {

using namespace particlesim;

struct SuiteCase {
    const char* name;
    SceneFamily family;
    SceneFamilyOptions options;
    const char* exercises;
};

// `particles` 0: the family's own count (ties, which takes none).
SceneFamilyOptions with(std::size_t particles, std::int64_t steps, OutputMode mode = OutputMode::print) {
    SceneFamilyOptions options;
    if (particles > 0) options.particles = particles;
    options.steps = steps;
    options.mode = mode;
    return options;
}

// From the smallest scene that shows a rule to scenes where only a fast,
// exact search keeps up.
std::vector<SuiteCase> suite_cases(std::uint64_t seed) {
    std::vector<SuiteCase> cases{
        {"cradle", SceneFamily::cradle, with(3, 14),
         "one collision per particle per step: the momentum crosses a touching row one disk per step; resting "
         "touching disks (A = 0) never collide"},
        {"ties", SceneFamily::ties, with(0, 6),
         "exact ties: wall before pair, lowest indices first, exact corners, t = 1 is a candidate, stopping at a "
         "wall reached exactly at the end of the step"},
        {"walls", SceneFamily::walls, with(24, 20),
         "disks starting on walls (wall collisions at t = 0) and pairs starting in contact"},
        {"line", SceneFamily::line, with(16, 60),
         "a row moving together into a wall: chains of head-on collisions, overlaps left by one-per-step"},
        {"fast", SceneFamily::fast, with(20, 10),
         "speeds of several box sides per step: the wall cut, stopping at walls after collisions"},
        {"random-small", SceneFamily::random, with(50, 50),
         "the rules' random scene (as simcli draws it) in a small box: many collisions per step"},
        {"gas", SceneFamily::gas, with(200, 50), "a gas at area fraction 0.3"},
        {"lattice", SceneFamily::lattice, with(300, 30),
         "a dense perturbed lattice: several candidates per particle, overlaps carried into the next step"},
        {"clusters", SceneFamily::clusters, with(400, 60), "dense clusters colliding in an empty box"},
        {"random-default", SceneFamily::random, with(1000, 100),
         "the default scene of the exercise (N = 1000, L = 20000, r = 1), 100 steps"},
        {"gas-perf", SceneFamily::gas, with(2000, 20, OutputMode::perf),
         "2000 disks at area fraction 0.05 in perf mode: only the final block, with the counters"},
    };
    cases[5].options.box_size = 200.0;
    cases[10].options.area_fraction = 0.05;
    for (SuiteCase& c : cases) c.options.seed = seed;
    return cases;
}

std::string shortest(double value) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

void write_expected_output(const Scene& scene, const std::string& path) {
    write_whole_file(path, [&](std::FILE* file) {
        SteppedOptions reference;
        reference.pair_search = PairSearch::brute_force;
        reference.threads = 1;
        SteppedSimulation engine(scene.world, scene.particles, reference);
        StateWriter writer(file);
        writer.write_state(0, engine.particles());
        const bool print = scene.mode == OutputMode::print;
        particlesim::run(engine, scene.steps, [&](std::int64_t step, std::span<const Particle> particles) {
            if (print && step < scene.steps) writer.write_state(step, particles);
        });
        writer.write_final(scene.steps, engine.particles());
        writer.flush();
    });
}

void write_text(const std::string& path, const std::string& text) {
    write_whole_file(path, [&](std::FILE* file) { std::fwrite(text.data(), 1, text.size(), file); });
}

// simcheck grade grades every *.in of the directory: scenes this run did not
// write (another suite's, or a user's) would be graded with it, so say so.
void warn_of_other_scenes(const std::string& directory, const std::vector<std::string>& written) {
    std::vector<std::string> others;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() == ".in" && std::find(written.begin(), written.end(), name) == written.end())
            others.push_back(name);
    }
    if (others.empty()) return;
    std::sort(others.begin(), others.end());
    std::string listed;
    for (std::size_t k = 0; k < others.size() && k < 3; ++k) listed += (k > 0 ? ", " : "") + others[k];
    if (others.size() > 3) listed += " and " + std::to_string(others.size() - 3) + " more";
    std::fprintf(stderr,
                 "simgen: %s also holds %zu scene%s this run did not write (%s): simcheck grade grades every *.in "
                 "there\n",
                 directory.c_str(), others.size(), others.size() == 1 ? "" : "s", listed.c_str());
}

}  // namespace

std::vector<std::string> suite_case_names() {
    std::vector<std::string> names;
    for (const SuiteCase& c : suite_cases(0)) names.emplace_back(c.name);
    return names;
}

void write_suite(const std::string& directory, std::uint64_t seed, const std::vector<std::string>& only) {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) throw std::runtime_error(directory + ": cannot make the directory: " + error.message());
    std::ostringstream manifest;
    manifest << "case\tfamily\tparticles\tbox\tradius\tsteps\tmode\texercises\n";
    std::vector<std::string> written;
    int number = 0;
    for (const SuiteCase& c : suite_cases(seed)) {
        ++number;
        if (!only.empty() && std::find(only.begin(), only.end(), c.name) == only.end()) continue;
        const Scene scene = make_family_scene(c.family, c.options);
        char prefix[16];
        std::snprintf(prefix, sizeof prefix, "%02d-", number);
        const std::string stem = directory + "/" + prefix + c.name;
        written.push_back(std::string(prefix) + c.name + ".in");
        std::ostringstream scene_text;
        write_scene(scene_text, scene);
        write_text(stem + ".in", scene_text.str());
        write_expected_output(scene, stem + ".out");
        const char* family = "";
        for (const SceneFamilyInfo& info : scene_families()) {
            if (info.family == c.family) family = info.name;
        }
        manifest << prefix << c.name << '\t' << family << '\t' << scene.particle_count << '\t'
                 << shortest(scene.world.box_size) << '\t' << shortest(scene.world.radius) << '\t' << scene.steps
                 << '\t' << (scene.mode == OutputMode::print ? "print" : "perf") << '\t' << c.exercises << '\n';
    }
    write_text(directory + "/manifest.tsv", manifest.str());
    warn_of_other_scenes(directory, written);
}

}  // namespace simgen
