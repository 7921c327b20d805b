#include "particlesim/scene.hpp"

#include "number_format.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace particlesim {

namespace {

// The most particles this machine can hold (bounded by memory and by the
// 32-bit particle indices), so that a header's N is refused before anything
// is allocated for it.
std::size_t max_particle_count() {
    // Everything a run keeps per particle (state, step and grid buffers) stays
    // well below this (docs/benchmarks.md gives the peak).
    constexpr std::size_t bytes_per_particle = 256;
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page_size = sysconf(_SC_PAGE_SIZE);
    const std::size_t by_memory = pages > 0 && page_size > 0 ? static_cast<std::size_t>(pages) / bytes_per_particle *
                                                                   static_cast<std::size_t>(page_size)
                                                             : std::size_t{1} << 24;
    return std::min<std::size_t>(by_memory, 0xfffffffeU);
}

using Text = std::string;

// Splits the input into lines of whitespace-separated tokens, refusing a line
// longer than max_line_length instead of buffering it.
class TokenLines {
public:
    explicit TokenLines(std::istream& input) : input_(input) {}

    // Advances to the next line that has tokens; false at the end.
    bool next() {
        for (;;) {
            if (!read_line()) return false;
            split();
            if (!tokens_.empty()) return true;
        }
    }

    [[nodiscard]] long number() const { return number_; }
    [[nodiscard]] const std::vector<std::string_view>& tokens() const { return tokens_; }

private:
    bool read_line() {
        line_.clear();
        bool any = false;
        std::streambuf& source = *input_.rdbuf();
        for (int c; (c = source.sbumpc()) != std::char_traits<char>::eof();) {
            any = true;
            if (c == '\n') break;
            if (line_.size() >= max_line_length) {
                throw InputError(number_ + 1, "line is longer than " + std::to_string(max_line_length) + " characters");
            }
            line_.push_back(static_cast<char>(c));
        }
        if (!any) return false;
        ++number_;
        return true;
    }

    void split() {
        tokens_.clear();
        const std::string_view text = line_;
        std::size_t at = 0;
        while (at < text.size()) {
            while (at < text.size() && is_space(text[at])) ++at;
            const std::size_t start = at;
            while (at < text.size() && !is_space(text[at])) ++at;
            if (at > start) tokens_.push_back(text.substr(start, at - start));
        }
    }

    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

    std::istream& input_;
    std::string line_;
    std::vector<std::string_view> tokens_;
    long number_ = 0;
};

// Yields the header's tokens one by one, across lines, with their line.
class HeaderTokens {
public:
    explicit HeaderTokens(TokenLines& lines) : lines_(lines) {}

    std::string_view take(std::string_view what) {
        while (index_ >= count_()) {
            if (!lines_.next())
                throw InputError(std::max(lines_.number(), 1L), "missing " + Text(what) + ": the input ends here");
            index_ = 0;
        }
        line_ = lines_.number();
        return lines_.tokens()[index_++];
    }
    [[nodiscard]] long line() const { return line_; }
    // Tokens left on the header's last line belong to the first particle line.
    [[nodiscard]] bool line_has_more() const { return index_ < count_(); }

private:
    [[nodiscard]] std::size_t count_() const { return lines_.number() == 0 ? 0 : lines_.tokens().size(); }

    TokenLines& lines_;
    std::size_t index_ = 0;
    long line_ = 0;
};

std::uint64_t parse_count(std::string_view token, std::string_view what, long line) {
    std::uint64_t value = 0;
    const bool digits_only =
        !token.empty() && std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (!digits_only)
        throw InputError(line, Text(what) + ": expected a non-negative integer, found \"" + Text(token) + "\"");
    if (error != std::errc{} || end != token.data() + token.size()) {
        throw InputError(line, Text(what) + " = " + Text(token) + " is too large");
    }
    return value;
}

double parse_real(std::string_view token, std::string_view what, long line) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc{} || end != token.data() + token.size() || !std::isfinite(value)) {
        if (error == std::errc::result_out_of_range)
            throw InputError(line, Text(what) + " = " + Text(token) + " is out of range");
        throw InputError(line, Text(what) + ": expected a finite number, found \"" + Text(token) + "\"");
    }
    if (std::fabs(value) > max_magnitude) {
        throw InputError(line, Text(what) + " = " + Text(token) + " exceeds the limit of 1e150 in magnitude");
    }
    return value + 0.0;  // -0 is read as 0
}

void read_header(HeaderTokens& header, Scene& scene, SceneLines& lines) {
    World& world = scene.world;
    const std::string_view count_text = header.take("N (number of particles)");
    const std::uint64_t count = parse_count(count_text, "N", header.line());
    lines.particle_count = header.line();
    if (count > max_particle_count()) {
        throw InputError(header.line(), "N = " + std::to_string(count) +
                                            " is more particles than this machine can hold (at most " +
                                            std::to_string(max_particle_count()) + ")");
    }
    scene.particle_count = static_cast<std::size_t>(count);

    const std::string_view box_text = header.take("L (box side)");
    world.box_size = parse_real(box_text, "L", header.line());
    lines.box_size = header.line();
    if (!(world.box_size > 0.0))
        throw InputError(header.line(), "L = " + format_short(world.box_size) + " must be > 0");

    const std::string_view radius_text = header.take("r (radius)");
    world.radius = parse_real(radius_text, "r", header.line());
    lines.radius = header.line();
    if (!(world.radius > 0.0)) throw InputError(header.line(), "r = " + format_short(world.radius) + " must be > 0");
    if (!(2.0 * world.radius <= world.box_size)) {
        throw InputError(header.line(), "r = " + format_short(world.radius) +
                                            " is too large: 2r must be <= L = " + format_short(world.box_size));
    }

    const std::string_view steps_text = header.take("S (number of steps)");
    const std::uint64_t steps = parse_count(steps_text, "S", header.line());
    if (steps > static_cast<std::uint64_t>(INT64_MAX))
        throw InputError(header.line(), "S = " + std::to_string(steps) + " is too large");
    scene.steps = static_cast<std::int64_t>(steps);
    lines.steps = header.line();

    const std::string_view mode = header.take("the output mode (print or perf)");
    lines.mode = header.line();
    if (mode == "print") {
        scene.mode = OutputMode::print;
    } else if (mode == "perf") {
        scene.mode = OutputMode::perf;
    } else {
        throw InputError(header.line(), "output mode: expected print or perf, found \"" + Text(mode) + "\"");
    }
}

void read_particle(const std::vector<std::string_view>& fields, long line, Scene& scene, std::vector<long>& seen_on) {
    if (fields.size() != 5) {
        throw InputError(line,
                         "a particle line has 5 fields \"i x y vx vy\", this one has " + std::to_string(fields.size()));
    }
    const std::uint64_t index = parse_count(fields[0], "particle index", line);
    if (index >= scene.particle_count) {
        throw InputError(line, "particle index " + Text(fields[0]) + " is outside [0, " +
                                   std::to_string(scene.particle_count - 1) + "]");
    }
    if (seen_on[index] != 0) {
        throw InputError(line, "particle " + std::to_string(index) + " is listed twice (first on line " +
                                   std::to_string(seen_on[index]) + ")");
    }
    seen_on[index] = line;

    const std::string label = "particle " + std::to_string(index) + ": ";
    const World& world = scene.world;
    Particle& p = scene.particles[index];
    const char* names[] = {"x", "y", "vx", "vy"};
    double values[4];
    for (int k = 0; k < 4; ++k) values[k] = parse_real(fields[k + 1], label + names[k], line);
    for (int k = 0; k < 2; ++k) {
        if (values[k] < world.lower() || values[k] > world.upper()) {
            throw InputError(line, label + names[k] + " = " + Text(fields[k + 1]) + " is outside [" +
                                       format_short(world.lower()) + ", " + format_short(world.upper()) + "]");
        }
    }
    p.position = Vec2(values[0], values[1]);
    p.velocity = Vec2(values[2], values[3]);
}

}  // namespace

Scene read_scene(std::istream& input, SceneLines* header_lines) {
    Scene scene;
    TokenLines lines(input);
    HeaderTokens header(lines);
    SceneLines read_on;
    read_header(header, scene, read_on);
    if (header_lines != nullptr) *header_lines = read_on;

    std::vector<long> seen_on;  // line of each particle, 0 while unseen
    std::size_t listed = 0;
    if (header.line_has_more())
        throw InputError(header.line(), "unexpected text after the output mode; particles go on lines of their own");
    while (lines.next()) {
        if (listed == scene.particle_count) {
            throw InputError(lines.number(),
                             scene.particle_count == 0
                                 ? "N = 0, but a particle line follows"
                                 : "more than N = " + std::to_string(scene.particle_count) + " particle lines");
        }
        if (listed == 0) {
            scene.particles.resize(scene.particle_count);
            seen_on.assign(scene.particle_count, 0);
        }
        read_particle(lines.tokens(), lines.number(), scene, seen_on);
        ++listed;
    }
    if (listed != 0 && listed != scene.particle_count) {
        throw InputError(std::max(lines.number(), 1L), "expected N = " + std::to_string(scene.particle_count) +
                                                           " particle lines or none, found " + std::to_string(listed));
    }
    return scene;
}

}  // namespace particlesim
