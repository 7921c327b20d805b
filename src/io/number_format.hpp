#pragma once
// Number formatting for output and messages, without iostreams or printf.

#include <cstddef>
#include <string>

namespace particlesim {

// Room that write_fixed8 may need for any finite double: sign, 309 integer
// digits (DBL_MAX is about 1.8e308), point, 8 decimals.
inline constexpr std::size_t max_fixed8_length = 320;

// Writes `value` exactly as printf("%.8f") would, except that a result of
// -0.00000000 is written as 0.00000000 (io.md). Returns the end.
char* write_fixed8(char* out, double value);

// The shortest text that reads back as `value` (at most 24 characters); -0 as 0.
char* write_shortest(char* out, double value);

// The shortest text that reads back as `value` (for messages quoting an input).
std::string format_short(double value);

// Four significant digits (for messages quoting a derived figure).
std::string format_brief(double value);

}  // namespace particlesim
