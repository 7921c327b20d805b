#pragma once
// A scene as io.md defines its input: the world, the number of steps, the
// output mode, and either the listed particles or, when none are listed, the
// number of particles to draw. read_scene() checks all of it before anything
// runs; memory stays bounded by the input's size whatever the header claims
// (lines are capped in length; nothing of size N is allocated before N
// particle lines have been read; N is checked against what this machine can hold).

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <cstddef>
#include <cstdint>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>
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

// Where each value was read (1-based lines), for messages about the scene
// that come after reading it (a random scene that cannot be placed, two
// listed disks that overlap where the exact engine needs them apart).
struct SceneLines {
    long particle_count = 0;
    long box_size = 0;
    long radius = 0;
    long steps = 0;
    long mode = 0;
    std::vector<long> particles;  // the line of each listed particle, in index order
};

// What is wrong, and on which line (1-based) of the input.
class InputError : public std::runtime_error {
public:
    InputError(long line, const std::string& message) : std::runtime_error(message), line_(line) {}
    [[nodiscard]] long line() const { return line_; }

private:
    long line_;
};

inline constexpr std::size_t max_line_length = 4096;

// Text of an input (a token, a line, a program's stderr) as a message shows
// it: every byte that would not show as itself (controls such as a
// terminal's escape sequences, DEL, anything outside ASCII) and backslash
// written as \xNN, so that no input can move, clear or retitle the terminal
// a message is printed on.
std::string printable_text(std::string_view text);
// The same in double quotes, a quote inside written as \x22.
std::string quoted_text(std::string_view text);

// Throws InputError naming the first problem found. `lines`, when given,
// receives where the header values were read. Listed centres lie in
// [r, L - r], or in [0, L) for a periodic box.
Scene read_scene(std::istream& input, SceneLines* lines = nullptr, Boundary boundary = Boundary::walls);

}  // namespace particlesim
