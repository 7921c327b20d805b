#include "particlesim/output_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace particlesim {

std::size_t split_fields(std::string_view text, std::span<std::string_view> fields) {
    std::size_t count = 0;
    for (std::size_t k = 0; k < text.size();) {
        if (text[k] == ' ' || text[k] == '\t') {
            ++k;
            continue;
        }
        std::size_t stop = k;
        while (stop < text.size() && text[stop] != ' ' && text[stop] != '\t') ++stop;
        if (count < fields.size()) fields[count] = text.substr(k, stop - k);
        ++count;
        k = stop;
    }
    return count;
}

bool is_fixed8(std::string_view token) {
    const std::size_t point = token.find('.');
    if (point == std::string_view::npos || token.size() - point - 1 != 8) return false;
    std::size_t first = token.front() == '-' ? 1 : 0;
    if (point == first) return false;
    for (std::size_t k = first; k < token.size(); ++k) {
        if (k != point && (token[k] < '0' || token[k] > '9')) return false;
    }
    return true;
}

OutputReader::OutputReader(std::FILE* in, std::string name) : in_(in), name_(std::move(name)) {
    if (in_ == nullptr)
        throw std::invalid_argument("particlesim::OutputReader: no FILE to read " + name_ + " from (null)");
}

// Refills the window of the input from the FILE in large blocks.
namespace {

// A number written with a sign the format never prints (printf's "%+.8f"):
// readable to a person, but not io.md's form, so named as such rather than
// as "not a number".
bool has_plus_sign(std::string_view token) {
    return token.size() > 1 && token.front() == '+' && token[1] != '+' && token[1] != '-';
}

std::string plus_sign_message(std::string_view what, std::string_view token) {
    return std::string(what) + " = " + quoted_text(token) + " has a '+' sign, which io.md's numbers never carry";
}

}  // namespace

bool OutputReader::fill() {
    if (begin_ > 0) {
        window_.erase(window_.begin(), window_.begin() + static_cast<std::ptrdiff_t>(begin_));
        begin_ = 0;
    }
    const std::size_t kept = window_.size();
    window_.resize(kept + block_size);
    const std::size_t got = std::fread(window_.data() + kept, 1, block_size, in_);
    window_.resize(kept + got);
    if (got == 0 && std::ferror(in_)) throw InputError(line_ + 1, "cannot be read");
    return got > 0;
}

bool OutputReader::next(OutputLine& out) {
    // The next line: up to '\n', or the end of the input.
    std::size_t end = 0;
    for (std::size_t searched = begin_;;) {
        const char* found =
            searched < window_.size()
                ? static_cast<const char*>(std::memchr(window_.data() + searched, '\n', window_.size() - searched))
                : nullptr;
        if (found) {
            end = static_cast<std::size_t>(found - window_.data());
            break;
        }
        searched = window_.size() - begin_;
        if (searched > particlesim::max_line_length) {
            throw InputError(line_ + 1,
                             "the line is longer than " + std::to_string(particlesim::max_line_length) + " characters");
        }
        if (!fill()) {
            if (window_.size() == begin_) return false;
            end = window_.size();
            break;
        }
        searched += begin_;
    }
    if (end - begin_ > particlesim::max_line_length) {
        throw InputError(line_ + 1,
                         "the line is longer than " + std::to_string(particlesim::max_line_length) + " characters");
    }
    ++line_;
    std::string_view text(window_.data() + begin_, end - begin_);
    begin_ = std::min(end + 1, window_.size());
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    out.line = line_;
    out.text.assign(text);

    std::string_view tokens[9];
    const std::size_t token_count = split_fields(text, tokens);
    if (token_count != 6 && token_count != 8) {
        throw InputError(line_, "expected \"s i x y vx vy\" (or \"... pc wc\" in the final block), found " +
                                    std::to_string(token_count) + " fields");
    }
    const auto integer = [&](std::string_view token, auto& value, const char* what) {
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size()) {
            if (has_plus_sign(token)) throw InputError(line_, plus_sign_message(what, token));
            throw InputError(line_, std::string(what) + " is not a whole number: " + quoted_text(token));
        }
    };
    integer(tokens[0], out.step, "the step");
    integer(tokens[1], out.index, "the particle index");
    if (!format_known_) {
        format_known_ = true;
        bool fixed = true;
        for (int k = 2; k < 6; ++k) fixed = fixed && is_fixed8(tokens[k]);
        format_ = fixed ? NumberFormat::fixed8 : NumberFormat::shortest;
    }
    double values[4];
    static constexpr const char* names[4] = {"x", "y", "vx", "vy"};
    for (int k = 0; k < 4; ++k) {
        const std::string_view token = tokens[k + 2];
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), values[k]);
        if (error != std::errc() || end != token.data() + token.size() || !std::isfinite(values[k])) {
            if (has_plus_sign(token)) throw InputError(line_, plus_sign_message(names[k], token));
            throw InputError(line_, std::string(names[k]) + " is not a finite number: " + quoted_text(token));
        }
        if (format_ == NumberFormat::fixed8 && !is_fixed8(token)) {
            throw InputError(line_, std::string(names[k]) + " = " + quoted_text(token) +
                                        " is not printed with 8 decimals (%.8f) like the first line");
        }
        if (format_ == NumberFormat::fixed8 && token == "-0.00000000") {
            throw InputError(line_,
                             std::string(names[k]) + " is printed as -0.00000000; io.md prints it as 0.00000000");
        }
    }
    out.particle = particlesim::Particle{};
    out.particle.position = particlesim::Vec2(values[0], values[1]);
    out.particle.velocity = particlesim::Vec2(values[2], values[3]);
    out.has_counters = token_count == 8;
    if (out.has_counters) {
        integer(tokens[6], out.particle.particle_collisions, "pc");
        integer(tokens[7], out.particle.wall_collisions, "wc");
    }
    return true;
}

}  // namespace particlesim
