#include "output_shape.hpp"

#include "particlesim/step_check.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>

namespace simcheck {

namespace {

using particlesim::OutputLine;
using particlesim::Particle;

// simcli --exact-numbers: the shortest text that reads back to the same double.
bool is_shortest(std::string_view token, double value) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string_view(text, static_cast<std::size_t>(end - text)) == token;
}

// Half a unit of the last digit printed: "1.500" 0.0005, "2e+03" 500, "17" 0.5.
double half_unit_of_last_digit(std::string_view token) {
    int exponent = 0;
    const std::size_t e = token.find_first_of("eE");
    if (e != std::string_view::npos) {
        std::from_chars(token.data() + e + 1 + (token[e + 1] == '+' ? 1 : 0), token.data() + token.size(), exponent);
        token = token.substr(0, e);
    }
    const std::size_t point = token.find('.');
    const int decimals = point == std::string_view::npos ? 0 : static_cast<int>(token.size() - point - 1);
    return 0.5 * std::pow(10.0, exponent - decimals);
}

struct Block {
    std::size_t first = 0;  // lines [first, last) of the parsed output
    std::size_t last = 0;
    std::int64_t step = 0;
    bool all_counters = true;
    bool no_counters = true;
};

std::string line_range(const std::vector<OutputLine>& lines, const Block& b) {
    return "lines " + std::to_string(lines[b.first].line) + "-" + std::to_string(lines[b.last - 1].line);
}

bool complete(const std::vector<OutputLine>& lines, const Block& b, std::size_t count) {
    if (b.last - b.first != count) return false;
    for (std::size_t k = b.first; k < b.last; ++k) {
        if (lines[k].index != k - b.first) return false;
    }
    return true;
}

bool same_states(const std::vector<OutputLine>& lines, const Block& a, const Block& b) {
    for (std::size_t k = 0; k < a.last - a.first; ++k) {
        const Particle& p = lines[a.first + k].particle;
        const Particle& q = lines[b.first + k].particle;
        if (p.position != q.position || p.velocity != q.velocity) return false;
    }
    return true;
}

// Parses one line loosely; empty optional and `why` set when it is no output line at all.
std::optional<OutputLine> parse_line(std::string_view text, long number, std::vector<std::string_view>& tokens,
                                     std::string& why) {
    tokens.assign(8, {});
    const std::size_t count = particlesim::split_fields(text, tokens);
    if (count != 6 && count != 8) {
        why = "line " + std::to_string(number) + " has " + std::to_string(count) +
              " fields, not \"s i x y vx vy\" (or \"... pc wc\")";
        return std::nullopt;
    }
    tokens.resize(count);
    OutputLine line;
    line.line = number;
    line.text.assign(text);
    const auto whole = [&](std::string_view token, auto& value) {
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        return error == std::errc() && end == token.data() + token.size();
    };
    double values[4];
    bool fine = whole(tokens[0], line.step) && whole(tokens[1], line.index);
    for (int k = 0; fine && k < 4; ++k) fine = whole(tokens[2 + static_cast<std::size_t>(k)], values[k]);
    for (int k = 0; fine && k < 4; ++k) fine = std::isfinite(values[k]);
    line.has_counters = tokens.size() == 8;
    if (fine && line.has_counters) {
        fine = whole(tokens[6], line.particle.particle_collisions) && whole(tokens[7], line.particle.wall_collisions);
    }
    if (!fine) {
        why = "line " + std::to_string(number) +
              " is not \"s i x y vx vy\" with whole s, i (pc, wc) and finite numbers: \"" + std::string(text) + "\"";
        return std::nullopt;
    }
    line.particle.position = particlesim::Vec2(values[0], values[1]);
    line.particle.velocity = particlesim::Vec2(values[2], values[3]);
    return line;
}

// Numbers: all in %.8f, all in the shortest round-trip text, or else a
// deviation, read as known within half a unit of the coarsest last digit.
class NumberFormats {
public:
    void add(std::string_view token, double value, long line) {
        if (!particlesim::is_fixed8(token)) {
            all_fixed8_ = false;
            if (first_other_.empty())
                first_other_ = "line " + std::to_string(line) + ": \"" + std::string(token) + "\"";
        }
        if (token == "-0.00000000" && negative_zero_line_ == 0) negative_zero_line_ = line;
        all_shortest_ = all_shortest_ && is_shortest(token, value);
        coarsest_ = std::max(coarsest_, half_unit_of_last_digit(token));
    }

    double finish(std::vector<std::string>& deviations) const {
        if (negative_zero_line_ != 0) {
            deviations.push_back("a zero printed as -0.00000000 (first: line " + std::to_string(negative_zero_line_) +
                                 "); io.md prints 0.00000000");
        }
        if (all_fixed8_) return particlesim::fixed8_uncertainty;
        if (all_shortest_) return 0.0;
        char text[32];
        std::snprintf(text, sizeof text, "%g", coarsest_);
        deviations.push_back("numbers not printed with %.8f (first: " + first_other_ +
                             "); each is read as known within " + text);
        return std::max(coarsest_, particlesim::fixed8_uncertainty);
    }

private:
    bool all_fixed8_ = true;
    bool all_shortest_ = true;
    double coarsest_ = 0.0;
    long negative_zero_line_ = 0;
    std::string first_other_;
};

}  // namespace

ShapedOutput read_shape(std::string_view text, const particlesim::Scene& scene) {
    ShapedOutput shaped;
    std::vector<std::string>& deviations = shaped.deviations;
    std::vector<OutputLine> lines;
    std::vector<std::string_view> tokens;
    NumberFormats numbers;
    long blank_line = 0, trailing_space_line = 0, spacing_line = 0;
    long number = 0;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        ++number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CR LF line ends are fine
        if (line.find_first_not_of(" \t") == std::string_view::npos) {
            if (blank_line == 0) blank_line = number;
            continue;
        }
        if ((line.back() == ' ' || line.back() == '\t') && trailing_space_line == 0) trailing_space_line = number;
        const std::string_view trimmed = line.substr(0, line.find_last_not_of(" \t") + 1);
        if (spacing_line == 0 &&
            (trimmed.front() == ' ' || trimmed.front() == '\t' || trimmed.find("  ") != std::string_view::npos ||
             trimmed.find('\t') != std::string_view::npos)) {
            spacing_line = number;
        }
        std::optional<OutputLine> parsed = parse_line(line, number, tokens, shaped.unreadable);
        if (!parsed) return shaped;
        for (std::size_t k = 2; k < 6; ++k) {
            numbers.add(tokens[k],
                        k < 4 ? parsed->particle.position[static_cast<int>(k - 2)]
                              : parsed->particle.velocity[static_cast<int>(k - 4)],
                        number);
        }
        lines.push_back(std::move(*parsed));
    }
    const auto at_line = [](long line) { return " (first: line " + std::to_string(line) + ")"; };
    if (blank_line != 0) deviations.push_back("blank lines" + at_line(blank_line));
    if (trailing_space_line != 0) deviations.push_back("trailing spaces" + at_line(trailing_space_line));
    if (spacing_line != 0) deviations.push_back("fields not separated by one space" + at_line(spacing_line));
    shaped.uncertainty = numbers.finish(deviations);

    // Blocks: a new one where the step changes or the index starts again.
    std::vector<Block> blocks;
    for (std::size_t k = 0; k < lines.size(); ++k) {
        if (blocks.empty() || lines[k].step != blocks.back().step || lines[k].index <= lines[k - 1].index) {
            blocks.push_back({k, k, lines[k].step, true, true});
        }
        Block& b = blocks.back();
        b.last = k + 1;
        b.all_counters = b.all_counters && lines[k].has_counters;
        b.no_counters = b.no_counters && !lines[k].has_counters;
    }
    const std::size_t count = scene.particle_count;
    const auto all_complete = [&] {
        return std::all_of(blocks.begin(), blocks.end(), [&](const Block& b) { return complete(lines, b, count); });
    };

    // A block printed twice in a row: one copy is set aside (the one without counters).
    for (std::size_t k = 0; k + 1 < blocks.size();) {
        const Block& a = blocks[k];
        const Block& b = blocks[k + 1];
        if (a.step != b.step || !complete(lines, a, count) || !complete(lines, b, count)) {
            ++k;
            continue;
        }
        if (!same_states(lines, a, b)) {
            shaped.unreadable = "step " + std::to_string(a.step) + " is printed twice with different states (" +
                                line_range(lines, a) + " and " + line_range(lines, b) + ")";
            return shaped;
        }
        const bool drop_first = !(a.all_counters && b.no_counters);
        deviations.push_back("step " + std::to_string(a.step) + " is printed twice (" + line_range(lines, a) + " and " +
                             line_range(lines, b) + "); the copy" +
                             ((drop_first ? a : b).no_counters ? " without counters" : "") + " was set aside");
        blocks.erase(blocks.begin() + static_cast<std::ptrdiff_t>(drop_first ? k : k + 1));
    }

    // No step-0 block: the scene's own particles, where it lists them.
    std::vector<OutputLine> initial;
    if (!blocks.empty() && blocks.front().step > 0 && all_complete()) {
        if (scene.is_random()) {
            shaped.unreadable =
                "the output has no step-0 block, and the scene is random: its initial state is not "
                "known";
            return shaped;
        }
        deviations.push_back("no step-0 block (the initial state); the scene's particles stand in for it");
        for (std::size_t i = 0; i < count; ++i) {
            OutputLine line;
            line.step = 0;
            line.index = i;
            line.particle = scene.particles[i];
            line.particle.particle_collisions = 0;
            line.particle.wall_collisions = 0;
            line.text = "(the scene's particle " + std::to_string(i) + ")";
            initial.push_back(std::move(line));
        }
    }

    // A perf-mode run that prints every step: the first and the final block are kept.
    const bool step_zero = !blocks.empty() && (blocks.front().step == 0 || !initial.empty());
    const std::size_t blocks_expected = initial.empty() ? 2 : 1;
    if (scene.mode == particlesim::OutputMode::perf && step_zero && blocks.size() > blocks_expected && all_complete() &&
        blocks.back().step == scene.steps) {
        deviations.push_back("every step printed, in a perf-mode scene (only the first and the final block belong)");
        blocks.erase(blocks.begin() + (initial.empty() ? 1 : 0), blocks.end() - 1);
    }

    // Counters: missing from the final block, or printed on every block.
    if (!blocks.empty() && complete(lines, blocks.back(), count)) {
        if (blocks.back().no_counters && count > 0) {
            deviations.push_back("the final block has no counters (pc wc); they are not judged");
            shaped.allowance.final_block_without_counters = true;
        }
        const bool every_block = blocks.size() > 1 && std::all_of(blocks.begin(), blocks.end(),
                                                                  [](const Block& b) { return b.all_counters; });
        if (every_block && count > 0) {
            deviations.push_back(
                "counters (pc wc) on every block, not only on the final one; the others were set aside");
            for (std::size_t k = 0; k + 1 < blocks.size(); ++k) {
                for (std::size_t l = blocks[k].first; l < blocks[k].last; ++l) lines[l].has_counters = false;
            }
        }
    }

    shaped.lines = std::move(initial);
    for (const Block& b : blocks) {
        for (std::size_t k = b.first; k < b.last; ++k) shaped.lines.push_back(std::move(lines[k]));
    }
    return shaped;
}

bool ShapedLines::next(OutputLine& out) {
    if (next_ >= shaped_.lines.size()) return false;
    out = shaped_.lines[next_++];
    return true;
}

long ShapedLines::lines_read() const {
    for (std::size_t k = next_; k > 0; --k) {
        if (shaped_.lines[k - 1].line > 0) return shaped_.lines[k - 1].line;
    }
    return 0;
}

}  // namespace simcheck
