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

// The lines of `text` from `at` up to `end` that are not blank (spaces and
// tabs only), one at a time, with a CR at a line's end removed; `number`
// counts every line passed, blank ones too.
bool next_line(std::string_view text, std::size_t end, std::size_t& at, long& number, std::string_view& line) {
    while (at < end) {
        std::size_t stop = text.find('\n', at);
        if (stop == std::string_view::npos || stop > end) stop = end;
        line = text.substr(at, stop - at);
        at = stop + 1;
        ++number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CR LF line ends are fine
        if (line.find_first_not_of(" \t") != std::string_view::npos) return true;
    }
    return false;
}

std::string line_range(const ShapedBlock& b) {
    return "lines " + std::to_string(b.first_line) + "-" + std::to_string(b.last_line);
}

bool complete(const ShapedBlock& b, std::size_t count) { return b.lines == count && b.in_order; }

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
        why =
            "line " + std::to_string(number) +
            " is not \"s i x y vx vy\" with whole s, i (pc, wc) and finite numbers: " + particlesim::quoted_text(text);
        return std::nullopt;
    }
    line.particle.position = particlesim::Vec2(values[0], values[1]);
    line.particle.velocity = particlesim::Vec2(values[2], values[3]);
    return line;
}

// Two complete blocks of the same particles: the same positions and velocities, line by line.
bool same_states(std::string_view text, const ShapedBlock& a, const ShapedBlock& b) {
    std::size_t at_a = a.begin, at_b = b.begin;
    long number_a = a.first_line - 1, number_b = b.first_line - 1;
    std::string_view line_a, line_b;
    std::vector<std::string_view> tokens;
    std::string why;
    while (next_line(text, a.end, at_a, number_a, line_a) && next_line(text, b.end, at_b, number_b, line_b)) {
        const std::optional<OutputLine> p = parse_line(line_a, number_a, tokens, why);
        const std::optional<OutputLine> q = parse_line(line_b, number_b, tokens, why);
        if (!p || !q || p->particle.position != q->particle.position || p->particle.velocity != q->particle.velocity)
            return false;
    }
    return true;
}

// Numbers: all in %.8f, all in the shortest round-trip text, or else a
// deviation, read as known within half a unit of the coarsest last digit.
class NumberFormats {
public:
    void add(std::string_view token, double value, long line) {
        if (!particlesim::is_fixed8(token)) {
            all_fixed8_ = false;
            if (first_other_.empty())
                first_other_ = "line " + std::to_string(line) + ": " + particlesim::quoted_text(token);
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

ShapedOutput read_shape(std::string text_kept, const particlesim::Scene& scene) {
    ShapedOutput shaped;
    shaped.text = std::move(text_kept);
    shaped.scene = &scene;
    const std::string_view text = shaped.text;
    std::vector<std::string>& deviations = shaped.deviations;
    std::vector<ShapedBlock> blocks;
    std::vector<std::string_view> tokens;
    NumberFormats numbers;
    long blank_line = 0, trailing_space_line = 0, spacing_line = 0;
    long number = 0;           // the line read last
    long previous_number = 0;  // the last line before it that is not blank
    std::uint64_t previous_index = 0;
    std::string_view line;
    for (std::size_t at = 0; next_line(text, text.size(), at, number, line); previous_number = number) {
        if (number > previous_number + 1 && blank_line == 0) blank_line = previous_number + 1;
        const auto begin = static_cast<std::size_t>(line.data() - text.data());
        const std::size_t end = std::min(at, text.size());  // past the line's end
        if ((line.back() == ' ' || line.back() == '\t') && trailing_space_line == 0) trailing_space_line = number;
        const std::string_view trimmed = line.substr(0, line.find_last_not_of(" \t") + 1);
        if (spacing_line == 0 &&
            (trimmed.front() == ' ' || trimmed.front() == '\t' || trimmed.find("  ") != std::string_view::npos ||
             trimmed.find('\t') != std::string_view::npos)) {
            spacing_line = number;
        }
        const std::optional<OutputLine> parsed = parse_line(line, number, tokens, shaped.unreadable);
        if (!parsed) return shaped;
        for (std::size_t k = 2; k < 6; ++k) {
            numbers.add(tokens[k],
                        k < 4 ? parsed->particle.position[static_cast<int>(k - 2)]
                              : parsed->particle.velocity[static_cast<int>(k - 4)],
                        number);
        }
        // Blocks: a new one where the step changes or the index starts again.
        if (blocks.empty() || parsed->step != blocks.back().step || parsed->index <= previous_index) {
            // An output of tiny blocks (a line each, a few bytes long) is left to the strict reader,
            // which reads it as it comes: its blocks would take more memory than its text.
            if (sizeof(ShapedBlock) * (blocks.size() + 1) > 2 * text.size() + 4096) {
                shaped.unreadable = "more blocks than an output of its size is read for its shape";
                return shaped;
            }
            blocks.push_back({begin, end, number, number, parsed->step, 0, true, true, true});
        }
        ShapedBlock& b = blocks.back();
        b.in_order = b.in_order && parsed->index == b.lines;
        ++b.lines;
        b.end = end;
        b.last_line = number;
        b.all_counters = b.all_counters && parsed->has_counters;
        b.no_counters = b.no_counters && !parsed->has_counters;
        previous_index = parsed->index;
    }
    if (number > previous_number && blank_line == 0) blank_line = previous_number + 1;  // blank lines at the end
    const auto at_line = [](long line) { return " (first: line " + std::to_string(line) + ")"; };
    if (blank_line != 0) deviations.push_back("blank lines" + at_line(blank_line));
    if (trailing_space_line != 0) deviations.push_back("trailing spaces" + at_line(trailing_space_line));
    if (spacing_line != 0) deviations.push_back("fields not separated by one space" + at_line(spacing_line));
    shaped.uncertainty = numbers.finish(deviations);

    const std::size_t count = scene.particle_count;
    const auto all_complete = [&] {
        return std::all_of(blocks.begin(), blocks.end(), [&](const ShapedBlock& b) { return complete(b, count); });
    };

    // A block printed twice in a row: one copy is set aside (the one without counters).
    for (std::size_t k = 0; k + 1 < blocks.size();) {
        const ShapedBlock& a = blocks[k];
        const ShapedBlock& b = blocks[k + 1];
        if (a.step != b.step || !complete(a, count) || !complete(b, count)) {
            ++k;
            continue;
        }
        if (!same_states(text, a, b)) {
            shaped.unreadable = "step " + std::to_string(a.step) + " is printed twice with different states (" +
                                line_range(a) + " and " + line_range(b) + ")";
            return shaped;
        }
        const bool drop_first = !(a.all_counters && b.no_counters);
        deviations.push_back("step " + std::to_string(a.step) + " is printed twice (" + line_range(a) + " and " +
                             line_range(b) + "); the copy" +
                             ((drop_first ? a : b).no_counters ? " without counters" : "") + " was set aside");
        blocks.erase(blocks.begin() + static_cast<std::ptrdiff_t>(drop_first ? k : k + 1));
    }

    // No step-0 block: the scene's own particles, where it lists them.
    if (!blocks.empty() && blocks.front().step > 0 && all_complete()) {
        if (scene.is_random()) {
            shaped.unreadable =
                "the output has no step-0 block, and the scene is random: its initial state is not "
                "known";
            return shaped;
        }
        deviations.push_back("no step-0 block (the initial state); the scene's particles stand in for it");
        shaped.scene_for_step_zero = true;
    }

    // A perf-mode run that prints every step: the first and the final block are kept.
    const bool step_zero = !blocks.empty() && (blocks.front().step == 0 || shaped.scene_for_step_zero);
    const std::size_t blocks_expected = shaped.scene_for_step_zero ? 1 : 2;
    if (scene.mode == particlesim::OutputMode::perf && step_zero && blocks.size() > blocks_expected && all_complete() &&
        blocks.back().step == scene.steps) {
        deviations.push_back("every step printed, in a perf-mode scene (only the first and the final block belong)");
        blocks.erase(blocks.begin() + (shaped.scene_for_step_zero ? 0 : 1), blocks.end() - 1);
    }

    // Counters: missing from the final block, or printed on every block.
    if (!blocks.empty() && complete(blocks.back(), count)) {
        if (blocks.back().no_counters && count > 0) {
            deviations.push_back("the final block has no counters (pc wc); they are not judged");
            shaped.allowance.final_block_without_counters = true;
        }
        const bool every_block = blocks.size() > 1 && std::all_of(blocks.begin(), blocks.end(),
                                                                  [](const ShapedBlock& b) { return b.all_counters; });
        if (every_block && count > 0) {
            deviations.push_back(
                "counters (pc wc) on every block, not only on the final one; the others were set aside");
            shaped.counters_on_final_only = true;
        }
    }
    shaped.blocks = std::move(blocks);
    return shaped;
}

bool ShapedLines::next(OutputLine& out) {
    const particlesim::Scene& scene = *shaped_.scene;
    if (shaped_.scene_for_step_zero && scene_particle_ < scene.particle_count) {
        const std::size_t i = scene_particle_++;
        out = OutputLine{};
        out.step = 0;
        out.index = i;
        out.particle = scene.particles[i];
        out.particle.particle_collisions = 0;
        out.particle.wall_collisions = 0;
        out.text = "(the scene's particle " + std::to_string(i) + ")";
        return true;
    }
    std::string why;
    for (; block_ < shaped_.blocks.size(); ++block_, started_ = false) {
        const ShapedBlock& b = shaped_.blocks[block_];
        if (!started_) {
            at_ = b.begin;
            line_ = b.first_line - 1;
            started_ = true;
        }
        std::string_view line;
        if (!next_line(shaped_.text, b.end, at_, line_, line)) continue;
        std::optional<OutputLine> parsed = parse_line(line, line_, tokens_, why);
        if (!parsed) throw particlesim::InputError(line_, why);  // read once already: cannot happen
        out = std::move(*parsed);
        if (shaped_.counters_on_final_only && block_ + 1 < shaped_.blocks.size()) out.has_counters = false;
        last_line_ = line_;
        return true;
    }
    return false;
}

}  // namespace simcheck
