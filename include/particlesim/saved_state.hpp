#pragma once
// The text both engines save their state in (their save() and restore()),
// and a program's own checkpoint around it (simcli's): whitespace-separated
// tokens, every double in the shortest form that reads back to the same bits
// ("inf" for never), so a saved state is exact and the same on every
// platform. Reading checks every token: a damaged or hostile file is refused
// with std::invalid_argument, never trusted.

#include "particlesim/engine.hpp"
#include "particlesim/particle.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace particlesim {

inline void save_number(std::ostream& out, double value) {
    char text[32];
    out << std::string_view(text, static_cast<std::size_t>(std::to_chars(text, text + sizeof text, value).ptr - text))
        << ' ';
}

inline void save_number(std::ostream& out, std::uint64_t value) {
    char text[24];
    out << std::string_view(text, static_cast<std::size_t>(std::to_chars(text, text + sizeof text, value).ptr - text))
        << ' ';
}

class SavedStateReader {
public:
    // `refusal` begins every error message, for example
    // "particlesim::ExactSimulation::restore: the saved state is damaged".
    SavedStateReader(std::istream& in, std::string refusal) : in_(in), refusal_(std::move(refusal)) {}

    void expect(std::string_view word) {
        const std::string token = next();
        if (token != word) fail("expected \"" + std::string(word) + "\"");
    }

    // The next token as it is (at most 64 characters).
    std::string word() { return next(); }

    double real() {
        const std::string token = next();
        double value = 0.0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc{} || end != token.data() + token.size() || std::isnan(value)) fail("bad number");
        return value;
    }

    std::uint64_t count(std::uint64_t max) {
        const std::string token = next();
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc{} || end != token.data() + token.size() || value > max) fail("bad count");
        return value;
    }

    [[noreturn]] void fail(const std::string& why) const { throw std::invalid_argument(refusal_ + " (" + why + ")"); }

private:
    std::string next() {
        std::string token;
        if (!(in_ >> std::setw(65) >> token)) fail("it ends early");
        if (token.size() > 64) fail("a token is too long");
        return token;
    }

    std::istream& in_;
    std::string refusal_;
};

// The parts both engines save alike: their totals, and a particle's state.
inline void save_counts(std::ostream& out, const StepCounts& counts) {
    save_number(out, counts.particle_collisions);
    save_number(out, counts.wall_collisions);
    save_number(out, counts.pair_tests);
}

inline StepCounts read_counts(SavedStateReader& in) {
    StepCounts counts;
    counts.particle_collisions = in.count(UINT64_MAX);
    counts.wall_collisions = in.count(UINT64_MAX);
    counts.pair_tests = in.count(UINT64_MAX);
    return counts;
}

inline void save_particle(std::ostream& out, const Particle& p) {
    for (const double value : {p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y()}) save_number(out, value);
    save_number(out, p.particle_collisions);
    save_number(out, p.wall_collisions);
}

// Read as saved; whether it fits a world is the engine's check (require_valid_scene).
inline Particle read_particle(SavedStateReader& in) {
    Particle p;
    const double x = in.real(), y = in.real(), vx = in.real(), vy = in.real();
    p.position = Vec2(x, y);
    p.velocity = Vec2(vx, vy);
    p.particle_collisions = in.count(UINT64_MAX);
    p.wall_collisions = in.count(UINT64_MAX);
    return p;
}

}  // namespace particlesim
