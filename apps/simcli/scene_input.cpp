#include "scene_input.hpp"

#include "common/input_path.hpp"

#include "particlesim/random_scene.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>

namespace simcli {

namespace {

particlesim::Scene read_input(const std::string& path, const std::string& name, particlesim::SceneLines& lines,
                              particlesim::Boundary boundary) {
    if (apps_common::names_a_directory(path)) throw BadInput(name + ": is a directory");
    if (path == "-") return particlesim::read_scene(std::cin, &lines, boundary);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw BadInput(name + ": cannot open: " + std::strerror(errno));
    return particlesim::read_scene(file, &lines, boundary);
}

}  // namespace

std::string at_line(const std::string& name, long line) { return name + ":" + std::to_string(line) + ": "; }

LoadedScene load_scene(const CliOptions& options) {
    LoadedScene loaded;
    loaded.name = options.scene_path == "-" ? "<stdin>" : options.scene_path;
    try {
        loaded.scene = read_input(options.scene_path, loaded.name, loaded.lines, options.boundary);
        loaded.particles =
            loaded.scene.is_random()
                ? particlesim::make_random_particles(loaded.scene.particle_count, loaded.scene.world, options.random)
                : std::move(loaded.scene.particles);
    } catch (const particlesim::InputError& e) {
        throw BadInput(at_line(loaded.name, e.line()) + e.what());
    } catch (const particlesim::SceneTooFull& e) {
        throw BadInput(at_line(loaded.name, loaded.lines.particle_count) + e.what());
    }
    return loaded;
}

}  // namespace simcli
