#include "particlesim/scene.hpp"

#include "input/scene_checks.hpp"
#include "io/number_format.hpp"
#include "particlesim/random_scene.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>
#include <vector>

namespace particlesim {

namespace {

using Text = std::string;

// Accepts one leading '+', as C's strtod and Python's float() do.
std::string_view without_plus(std::string_view token) {
    return token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+' ? token.substr(1) : token;
}

// Splits the input into lines of whitespace-separated tokens, refusing a line
// longer than max_line_length instead of buffering it. The input is read in
// chunks (a scene is read to its end anyway): a character at a time, the
// reading took longer than a million particles' whole setup.
class TokenLines {
public:
    explicit TokenLines(std::istream& input) : source_(*input.rdbuf()), chunk_(chunk_size) {}

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
    static constexpr std::size_t chunk_size = 1 << 16;

    bool read_line() {
        line_.clear();
        bool any = false;
        for (;;) {
            if (at_ == filled_ && !refill()) break;
            any = true;
            const char* const start = chunk_.data() + at_;
            const auto available = static_cast<std::size_t>(filled_ - at_);
            const auto* newline = static_cast<const char*>(std::memchr(start, '\n', available));
            const std::size_t length = newline != nullptr ? static_cast<std::size_t>(newline - start) : available;
            line_.append(start, length);
            at_ += length + (newline != nullptr ? 1 : 0);
            // The length excludes the line ending: one '\r' may follow a full line.
            if (line_.size() > max_line_length && !(line_.size() == max_line_length + 1 && line_.back() == '\r')) {
                throw InputError(number_ + 1,
                                 "the line is longer than " + std::to_string(max_line_length) + " characters");
            }
            if (newline != nullptr) break;
        }
        if (!any) return false;
        if (number_ == 0) skip_byte_order_mark();
        ++number_;
        return true;
    }

    bool refill() {
        at_ = 0;
        filled_ = source_.sgetn(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
        return filled_ > 0;
    }

    // Editors on Windows start UTF-8 files with EF BB BF; it is not part of the scene.
    void skip_byte_order_mark() {
        constexpr std::string_view mark = "\xEF\xBB\xBF";
        if (std::string_view(line_).starts_with(mark)) line_.erase(0, mark.size());
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

    std::streambuf& source_;
    std::vector<char> chunk_;
    std::streamsize at_ = 0;      // the next unread character of the chunk
    std::streamsize filled_ = 0;  // characters in the chunk
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

std::uint64_t parse_count(std::string_view text, std::string_view what, long line) {
    const std::string_view token = without_plus(text);
    std::uint64_t value = 0;
    const bool digits_only =
        !token.empty() && std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (!digits_only)
        throw InputError(line, Text(what) + ": expected a non-negative integer, found " + quoted_text(text));
    if (error != std::errc{} || end != token.data() + token.size()) {
        throw InputError(line, Text(what) + " = " + Text(token) + " is too large");
    }
    return value;
}

// A finite number in the accepted range. `name()` names it in a message; it
// is called only on error, so that a million particles build no labels.
template <typename Name>
double parse_real(std::string_view text, const Name& name, long line) {
    const std::string_view token = without_plus(text);
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    const bool whole_token = end == token.data() + token.size();
    if (error == std::errc::result_out_of_range && whole_token) {
        throw InputError(line, Text(name()) + " = " + Text(token) +
                                   " is beyond the range of a double (and of the accepted range, magnitudes "
                                   "at most 1e60)");
    }
    if (error != std::errc{} || !whole_token || !std::isfinite(value))
        throw InputError(line, Text(name()) + ": expected a finite number, found " + quoted_text(text));
    if (std::fabs(value) > max_magnitude) {
        throw InputError(line, Text(name()) + " = " + Text(token) +
                                   " is beyond the accepted range (magnitudes at most 1e60; docs/accepted-range.md)");
    }
    return value + 0.0;  // -0 is read as 0
}

// L and r: positive and inside the accepted range.
double parse_length(std::string_view text, std::string_view what, long line) {
    const double value = parse_real(
        text, [&] { return what; }, line);
    if (!(value > 0.0)) throw InputError(line, Text(what) + " = " + format_short(value) + " must be > 0");
    if (value < min_length) {
        throw InputError(line, Text(what) + " = " + format_short(value) +
                                   " is below the accepted range (L and r at least 1e-60; docs/accepted-range.md)");
    }
    return value;
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
    world.box_size = parse_length(box_text, "L", header.line());
    lines.box_size = header.line();

    const std::string_view radius_text = header.take("r (radius)");
    world.radius = parse_length(radius_text, "r", header.line());
    lines.radius = header.line();
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
        throw InputError(header.line(), "output mode: expected print or perf, found " + quoted_text(mode));
    }
}

// The particle lines in the order they were read. Memory grows with the lines
// actually present, never with the header's N: only once all N are there is
// anything of size N allocated (to put them in index order).
struct ListedParticles {
    std::vector<Particle> particles;
    std::vector<std::uint32_t> indices;
    std::vector<long> lines;
};

void read_particle(const std::vector<std::string_view>& fields, long line, const Scene& scene, Boundary boundary,
                   ListedParticles& listed) {
    if (fields.size() != 5) {
        throw InputError(line,
                         "a particle line has 5 fields \"i x y vx vy\", this one has " + std::to_string(fields.size()));
    }
    const std::uint64_t index = parse_count(fields[0], "particle index", line);
    if (index >= scene.particle_count) {
        throw InputError(line, "particle index " + std::to_string(index) + " is outside [0, " +
                                   std::to_string(scene.particle_count - 1) + "]");
    }
    // The label is built only for a message: a million particles need none.
    const auto label = [&](int k) {
        constexpr const char* names[] = {"x", "y", "vx", "vy"};
        return "particle " + std::to_string(index) + ": " + names[k];
    };
    const World& world = scene.world;
    double values[4];
    for (int k = 0; k < 4; ++k)
        values[k] = parse_real(
            fields[k + 1], [&] { return label(k); }, line);
    for (int k = 0; k < 2; ++k) {
        if (boundary == Boundary::periodic) {
            if (!(values[k] >= 0.0 && values[k] < world.box_size)) {
                throw InputError(line, label(k) + " = " + format_short(values[k]) + " is outside [0, " +
                                           format_short(world.box_size) + ") (a periodic box)");
            }
        } else if (values[k] < world.lower() || values[k] > world.upper()) {
            throw InputError(line, label(k) + " = " + format_short(values[k]) + " is outside [" +
                                       format_short(world.lower()) + ", " + format_short(world.upper()) + "]");
        }
    }
    Particle p;
    p.position = Vec2(values[0], values[1]);
    p.velocity = Vec2(values[2], values[3]);
    listed.particles.push_back(p);
    listed.indices.push_back(static_cast<std::uint32_t>(index));
    listed.lines.push_back(line);
}

// All N lines are there: each index once, then index order.
void put_in_index_order(ListedParticles& listed, Scene& scene, std::vector<long>* particle_lines) {
    // Listed in index order already, as simgen and simcli write scenes: the
    // lists become the scene's, without a copy of a large scene's particles.
    bool in_order = true;
    for (std::uint32_t k = 0; k < listed.indices.size() && in_order; ++k) in_order = listed.indices[k] == k;
    if (in_order) {
        scene.particles = std::move(listed.particles);
        if (particle_lines != nullptr) *particle_lines = std::move(listed.lines);
        return;
    }
    constexpr std::uint32_t unseen = 0xffffffffU;
    std::vector<std::uint32_t> read_as(scene.particle_count, unseen);
    for (std::uint32_t k = 0; k < listed.indices.size(); ++k) {
        std::uint32_t& first = read_as[listed.indices[k]];
        if (first != unseen) {
            throw InputError(listed.lines[k], "particle " + std::to_string(listed.indices[k]) +
                                                  " is listed twice (first on line " +
                                                  std::to_string(listed.lines[first]) + ")");
        }
        first = k;
    }
    scene.particles.resize(scene.particle_count);
    if (particle_lines != nullptr) particle_lines->resize(scene.particle_count);
    for (std::size_t i = 0; i < scene.particle_count; ++i) {
        scene.particles[i] = listed.particles[read_as[i]];
        if (particle_lines != nullptr) (*particle_lines)[i] = listed.lines[read_as[i]];
    }
}

// A random scene draws speeds up to max(L/(8r), L/4): refused when that
// leaves the accepted range (a tiny r in a large box).
void check_random_speeds(const Scene& scene, const SceneLines& lines) {
    const double fastest = default_speed_range(scene.world).max;
    if (fastest > max_magnitude) {
        throw InputError(lines.radius, "a random scene with L = " + format_short(scene.world.box_size) +
                                           " and r = " + format_short(scene.world.radius) +
                                           " draws speeds up to L/(8r) = " + format_brief(fastest) +
                                           ", beyond the accepted range (at most 1e60); list the particles instead");
    }
}

}  // namespace

Scene read_scene(std::istream& input, SceneLines* header_lines, Boundary boundary) {
    Scene scene;
    TokenLines lines(input);
    HeaderTokens header(lines);
    SceneLines read_on;
    read_header(header, scene, read_on);

    ListedParticles listed;
    if (header.line_has_more())
        throw InputError(header.line(), "unexpected text after the output mode; particles go on lines of their own");
    while (lines.next()) {
        if (listed.particles.size() == scene.particle_count) {
            throw InputError(lines.number(),
                             scene.particle_count == 0
                                 ? "N = 0, but a particle line follows"
                                 : "more than N = " + std::to_string(scene.particle_count) + " particle lines");
        }
        read_particle(lines.tokens(), lines.number(), scene, boundary, listed);
    }
    if (!listed.particles.empty() && listed.particles.size() != scene.particle_count) {
        throw InputError(std::max(lines.number(), 1L), "expected N = " + std::to_string(scene.particle_count) +
                                                           " particle lines or none, found " +
                                                           std::to_string(listed.particles.size()));
    }
    if (!listed.particles.empty()) {
        put_in_index_order(listed, scene, header_lines != nullptr ? &read_on.particles : nullptr);
    }
    if (scene.is_random()) check_random_speeds(scene, read_on);
    if (header_lines != nullptr) *header_lines = std::move(read_on);
    return scene;
}

}  // namespace particlesim
