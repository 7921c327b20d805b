#include "io/number_format.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace particlesim {

namespace {

// "00" to "99": the decimals are written two digits at a time, in two
// independent halves of four (a digit at a time was a quarter of writing a
// million particles' state).
constexpr auto digit_pairs = [] {
    std::array<char, 200> pairs{};
    for (int k = 0; k < 100; ++k) {
        pairs[2 * k] = static_cast<char>('0' + k / 10);
        pairs[2 * k + 1] = static_cast<char>('0' + k % 10);
    }
    return pairs;
}();

void write_four_digits(char* out, std::uint32_t value) {
    std::memcpy(out, &digit_pairs[2 * (value / 100)], 2);
    std::memcpy(out + 2, &digit_pairs[2 * (value % 100)], 2);
}

char* write_eight_digits(char* out, std::uint64_t value) {
    const auto eight = static_cast<std::uint32_t>(value);
    write_four_digits(out, eight / 10000);
    write_four_digits(out + 4, eight % 10000);
    return out + 8;
}

char* drop_negative_zero(char* begin, char* end) {
    if (*begin != '-') return end;
    for (const char* c = begin + 1; c != end; ++c) {
        if (*c != '0' && *c != '.') return end;
    }
    std::memmove(begin, begin + 1, static_cast<std::size_t>(end - begin - 1));
    return end - 1;
}

}  // namespace

char* write_fixed8(char* out, double value) {
    // Fast path, exact: split off the integer part (exactly), scale the
    // fraction (error < 1e-8 of a unit in the last printed place) and round.
    // Near a tie of the last place the scaled value is too coarse to decide,
    // so those cases (and huge values) go to std::to_chars, which rounds the
    // exact binary value as printf does.
    const double magnitude = std::fabs(value);
    if (magnitude < 0x1.0p52) {
        const double whole = std::trunc(magnitude);
        const double scaled = (magnitude - whole) * 1e8;
        const double scaled_whole = std::floor(scaled);
        const double rest = scaled - scaled_whole;
        if (std::fabs(rest - 0.5) > 1e-6) {
            auto integer = static_cast<std::uint64_t>(whole);
            auto decimals = static_cast<std::uint64_t>(scaled_whole) + (rest > 0.5 ? 1 : 0);
            if (decimals == 100000000) {
                decimals = 0;
                ++integer;
            }
            if (value < 0.0 && (integer != 0 || decimals != 0)) *out++ = '-';
            out = std::to_chars(out, out + 20, integer).ptr;
            *out++ = '.';
            return write_eight_digits(out, decimals);
        }
    }
    char* const begin = out;
    char* const end = std::to_chars(out, out + max_fixed8_length, value, std::chars_format::fixed, 8).ptr;
    return drop_negative_zero(begin, end);
}

char* write_shortest(char* out, double value) { return std::to_chars(out, out + 32, value + 0.0).ptr; }

std::string format_short(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

std::string format_brief(double value) {
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 4);
    return std::string(text, result.ptr);
}

}  // namespace particlesim
