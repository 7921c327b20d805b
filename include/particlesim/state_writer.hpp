#pragma once
// Writes states in the output format of io.md through a large buffer, with
// hand-rolled number formatting (no iostreams, no printf per number).

#include "particlesim/particle.hpp"

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>

namespace particlesim {

// The output could not be written (a full disk, a closed pipe, ...).
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// How numbers are written: io.md's %.8f, or (--exact-numbers) the shortest
// text that reads back to the same double, for boxes far from the 8-decimal scale.
enum class NumberFormat { fixed8, shortest };

class StateWriter {
public:
    // `out`: not owned, not closed; null throws std::invalid_argument.
    explicit StateWriter(std::FILE* out, NumberFormat format = NumberFormat::fixed8);

    // "s i x y vx vy" for every particle. A block may be written in parts:
    // `first_index` is the index i of the part's first particle.
    void write_state(std::int64_t step, std::span<const Particle> particles, std::size_t first_index = 0);
    // "s i x y vx vy pc wc" for every particle: the final block (in parts, likewise).
    void write_final(std::int64_t step, std::span<const Particle> particles, std::size_t first_index = 0);
    // Hands everything buffered to the FILE and flushes it; throws OutputError.
    void flush();
    // For a periodic box of side `side` (positions in [0, side)): a position
    // that 8 decimals would round up to `side` (19.9999999996 in a box of
    // 20) is written as 0.00000000, the same place within the printing's
    // rounding, so that printed positions stay in [0, side) and read back as
    // a periodic scene. Throws std::invalid_argument unless 0 < side < inf.
    void wrap_positions_into(double side);

private:
    void write_block(std::int64_t step, std::span<const Particle> particles, std::size_t first_index,
                     bool with_counters);
    void drain();
    // `position`, or 0 where its 8 decimals read as the side or more.
    [[nodiscard]] double printed_in_box(double position) const;

    std::FILE* out_;
    NumberFormat format_;
    double wrap_side_ = 0.0;  // wrap_positions_into()'s side; 0: positions as they are
    double wrap_from_ = std::numeric_limits<double>::infinity();  // positions from here on may round up to it
    // Left uninitialised: a page is touched only when output reaches it (a
    // first touch of a page is slow in a virtual machine, and most runs
    // write far less than the buffer holds).
    std::unique_ptr<char[]> buffer_;
    std::size_t used_ = 0;
};

}  // namespace particlesim
