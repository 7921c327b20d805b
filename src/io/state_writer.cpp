#include "particlesim/state_writer.hpp"

#include "io/number_format.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace particlesim {

namespace {

constexpr std::size_t buffer_size = std::size_t{1} << 20;
// The longest line: two integers, four numbers, two counters, separators.
constexpr std::size_t longest_state_line = 4 * 21 + 4 * (max_fixed8_length + 1) + 1;

}  // namespace

StateWriter::StateWriter(std::FILE* out, NumberFormat format)
    : out_(out), format_(format), buffer_(std::make_unique_for_overwrite<char[]>(buffer_size)) {
    if (out_ == nullptr) throw std::invalid_argument("particlesim::StateWriter: no FILE to write to (null)");
}

void StateWriter::write_state(std::int64_t step, std::span<const Particle> particles, std::size_t first_index) {
    write_block(step, particles, first_index, false);
}

void StateWriter::write_final(std::int64_t step, std::span<const Particle> particles, std::size_t first_index) {
    write_block(step, particles, first_index, true);
}

void StateWriter::write_block(std::int64_t step, std::span<const Particle> particles, std::size_t first_index,
                              bool with_counters) {
    char step_text[24];
    const std::size_t step_length =
        static_cast<std::size_t>(std::to_chars(step_text, step_text + 24, step).ptr - step_text);
    for (std::size_t i = 0; i < particles.size(); ++i) {
        if (buffer_size - used_ < longest_state_line) drain();
        char* out = buffer_.get() + used_;
        std::memcpy(out, step_text, step_length);
        out += step_length;
        *out++ = ' ';
        out = std::to_chars(out, out + 21, first_index + i).ptr;
        const Particle& p = particles[i];
        double x = p.position.x(), y = p.position.y();
        if (x >= wrap_from_) x = printed_in_box(x);
        if (y >= wrap_from_) y = printed_in_box(y);
        for (const double value : {x, y, p.velocity.x(), p.velocity.y()}) {
            *out++ = ' ';
            out = format_ == NumberFormat::fixed8 ? write_fixed8(out, value) : write_shortest(out, value);
        }
        if (with_counters) {
            *out++ = ' ';
            out = std::to_chars(out, out + 21, p.particle_collisions).ptr;
            *out++ = ' ';
            out = std::to_chars(out, out + 21, p.wall_collisions).ptr;
        }
        *out++ = '\n';
        used_ = static_cast<std::size_t>(out - buffer_.get());
    }
}

void StateWriter::wrap_positions_into(double side) {
    if (!(side > 0.0 && std::isfinite(side)))
        throw std::invalid_argument(
            "particlesim::StateWriter::wrap_positions_into: the side must be finite and "
            "positive, not " +
            format_short(side));
    wrap_side_ = side;
    // Only 8 decimals round up, and only a position within a printed place of the side.
    if (format_ == NumberFormat::fixed8) wrap_from_ = side - 1e-8;
}

double StateWriter::printed_in_box(double position) const {
    char text[max_fixed8_length + 1];
    double printed = 0.0;
    std::from_chars(text, write_fixed8(text, position), printed);
    return printed >= wrap_side_ ? 0.0 : position;
}

void StateWriter::drain() {
    if (used_ == 0) return;
    if (std::fwrite(buffer_.get(), 1, used_, out_) != used_) {
        throw OutputError(std::string("cannot write the output: ") + std::strerror(errno));
    }
    used_ = 0;
}

void StateWriter::flush() {
    drain();
    if (std::fflush(out_) != 0) throw OutputError(std::string("cannot write the output: ") + std::strerror(errno));
}

}  // namespace particlesim
