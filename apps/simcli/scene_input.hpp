#pragma once
// The scene simcli runs: read from a file or stdin, its particles listed or
// placed at random, every failure a BadInput naming the file and line.

#include "cli_options.hpp"

#include "particlesim/particle.hpp"
#include "particlesim/scene.hpp"

#include <string>
#include <vector>

namespace simcli {

struct LoadedScene {
    std::string name;  // the file's name in messages: its path, or <stdin>
    particlesim::Scene scene;
    particlesim::SceneLines lines;  // where each part of the scene was read, for messages
    std::vector<particlesim::Particle> particles;
};

// Throws BadInput.
LoadedScene load_scene(const CliOptions& options);

// "NAME:LINE: ", the start of a message about a line of the scene.
std::string at_line(const std::string& name, long line);

}  // namespace simcli
