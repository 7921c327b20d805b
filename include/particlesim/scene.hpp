#pragma once
// A scene as io.md defines its input: the world, the number of steps, the
// output mode, and either the listed particles or, when none are listed, the
// number of particles to draw. read_scene() checks all of it before anything
// runs; memory stays bounded whatever the input (lines are capped in length,
// N is checked against what this machine can hold before anything is allocated).

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace particlesim {

enum class OutputMode { print, perf };

struct Scene {
    World world;
    std::int64_t steps = 0;  // S
    OutputMode mode = OutputMode::perf;
    std::size_t particle_count = 0;   // N
    std::vector<Particle> particles;  // index order; empty for a random scene

    [[nodiscard]] bool is_random() const { return particles.empty() && particle_count > 0; }
};

// Where each header value was read (1-based lines), for messages about the
// scene that come after reading it (a random scene that cannot be placed).
struct SceneLines {
    long particle_count = 0;
    long box_size = 0;
    long radius = 0;
    long steps = 0;
    long mode = 0;
};

// What is wrong, and on which line (1-based) of the input.
class InputError : public std::runtime_error {
public:
    InputError(long line, const std::string& message) : std::runtime_error(message), line_(line) {}
    [[nodiscard]] long line() const { return line_; }

private:
    long line_;
};

// Coordinates, sizes and velocities are limited to this magnitude so that
// every square the physics forms stays finite.
inline constexpr double max_magnitude = 1e150;
inline constexpr std::size_t max_line_length = 4096;

// Throws InputError naming the first problem found. `lines`, when given,
// receives where the header values were read.
Scene read_scene(std::istream& input, SceneLines* lines = nullptr);

}  // namespace particlesim
