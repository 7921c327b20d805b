#pragma once
// Reads an output in io.md's format (what StateWriter writes) line by line,
// without holding it: one line "s i x y vx vy" (or, in the final block,
// "... pc wc") at a time. Lines that are not such a line at all are format
// errors (InputError); which step and particle a well-formed line names is the
// caller's business (simcheck judges it).

#include "particlesim/particle.hpp"
#include "particlesim/scene.hpp"
#include "particlesim/state_writer.hpp"

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace particlesim {

// Splits a line at spaces and tabs into `fields` (as many as fit); returns
// how many fields the line has.
std::size_t split_fields(std::string_view line, std::span<std::string_view> fields);

// Whether a number is written as io.md's %.8f writes it ("-12.50000000").
bool is_fixed8(std::string_view number);

struct OutputLine {
    long line = 0;  // 1-based
    std::int64_t step = 0;
    std::uint64_t index = 0;
    Particle particle;  // counters only when has_counters
    bool has_counters = false;
    std::string text;  // for reports
};

class OutputReader {
public:
    OutputReader(std::FILE* in, std::string name);  // `in`: not owned; null throws std::invalid_argument

    // The next line, or false at the end. Throws InputError.
    bool next(OutputLine& out);
    // How the numbers are written, decided by the first line: io.md's %.8f
    // (a value is known within 0.5e-8), or the shortest round-trip text
    // (simcli --exact-numbers: known exactly).
    [[nodiscard]] NumberFormat format() const { return format_; }
    [[nodiscard]] long lines_read() const { return line_; }
    [[nodiscard]] const std::string& name() const { return name_; }

private:
    static constexpr std::size_t block_size = 1 << 20;
    bool fill();

    std::FILE* in_;
    std::string name_;
    std::vector<char> window_;  // read but not yet consumed from begin_
    std::size_t begin_ = 0;
    long line_ = 0;
    bool format_known_ = false;
    NumberFormat format_ = NumberFormat::fixed8;
};

}  // namespace particlesim
