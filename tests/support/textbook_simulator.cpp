// The textbook implementation (textbook_rules.hpp) as a program of the
// exercise, for simcheck grade to run: the scene on stdin, the output on
// stdout, with one classic mistake injected (its name as the argument) or the
// last step printed twice, the first time without counters (as a peer's
// OpenMP program does).
//   textbook_simulator [none | no-stop-at-wall | two-collisions-per-step | ... | last-block-twice]

#include "textbook_rules.hpp"

#include "particlesim/scene.hpp"

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const std::string wanted = argc > 1 ? argv[1] : "none";
    textbook::Mistake mistake = textbook::Mistake::none;
    const bool last_block_twice = wanted == "last-block-twice";
    bool known = last_block_twice;
    for (int m = 0; m <= static_cast<int>(textbook::Mistake::repeated_line); ++m) {
        std::string name = textbook::mistake_name(static_cast<textbook::Mistake>(m));
        for (char& c : name) c = c == ' ' ? '-' : c;
        if (name == wanted) {
            mistake = static_cast<textbook::Mistake>(m);
            known = true;
        }
    }
    if (!known) {
        std::fprintf(stderr, "textbook_simulator: no mistake named %s\n", wanted.c_str());
        return 2;
    }
    try {
        const particlesim::Scene scene = particlesim::read_scene(std::cin);
        if (scene.is_random()) {
            std::fprintf(stderr, "textbook_simulator: lists of particles only\n");
            return 2;
        }
        std::string out = textbook::output(scene, scene.particles, mistake);
        if (last_block_twice && scene.particle_count > 0) {
            // The final block again in front of itself, without its counters.
            std::vector<std::size_t> line_starts;
            for (std::size_t at = 0; at < out.size(); at = out.find('\n', at) + 1) line_starts.push_back(at);
            const std::size_t start = line_starts[line_starts.size() - scene.particle_count];
            std::string bare;
            for (std::size_t at = start; at < out.size();) {
                const std::size_t end = out.find('\n', at);
                std::string line = out.substr(at, end - at);
                line = line.substr(0, line.rfind(' '));
                line = line.substr(0, line.rfind(' '));
                bare += line + "\n";
                at = end + 1;
            }
            out.insert(start, bare);
        }
        std::fwrite(out.data(), 1, out.size(), stdout);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "textbook_simulator: %s\n", e.what());
        return 2;
    }
    return 0;
}
