#pragma once
// Reads and validates a scene (io.md "Input scene") before anything runs.
// Memory stays bounded whatever the input: lines are capped in length and N is
// checked against what this machine can hold before anything is allocated.

#include "particlesim/scene.hpp"

#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>

namespace particlesim {

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

// The most particles this machine can hold (bounded by memory and by the
// 32-bit particle indices).
std::size_t max_particle_count();

// Throws InputError naming the first problem found.
Scene read_scene(std::istream& input);

}  // namespace particlesim
