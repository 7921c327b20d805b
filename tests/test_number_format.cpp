// write_fixed8 must print exactly what printf("%.8f") prints (but for -0), for
// every finite double; write_shortest must read back to the same double.

#include "check.hpp"

#include "core/random.hpp"
#include "io/number_format.hpp"
#include "particlesim/state_writer.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace particlesim;

namespace {

std::string fast(double value) {
    char text[max_fixed8_length + 1];
    return std::string(text, write_fixed8(text, value));
}

std::string reference(double value) {
    char text[400];
    std::snprintf(text, sizeof text, "%.8f", value);
    std::string s = text;
    if (s == "-0.00000000") s = "0.00000000";
    return s;
}

// The lines StateWriter writes for one particle at (x, y) moving at (vx, vy).
std::string written_line(double x, double y, double vx, double vy, double wrap_side, NumberFormat format) {
    char* text = nullptr;
    std::size_t size = 0;
    std::FILE* out = open_memstream(&text, &size);
    {
        StateWriter writer(out, format);
        if (wrap_side > 0.0) writer.wrap_positions_into(wrap_side);
        Particle p;
        p.position = Vec2(x, y);
        p.velocity = Vec2(vx, vy);
        writer.write_state(3, std::vector<Particle>{p});
        writer.flush();
    }
    std::fclose(out);
    std::string line(text, size);
    std::free(text);
    return line;
}

// In a periodic box of 20, a position that 8 decimals round up to 20 is
// written as 0 (its image, within the rounding); no other number changes.
void positions_wrapped_into_a_periodic_box() {
    const double nearly = 19.9999999996;
    CHECK_EQ(reference(nearly), std::string("20.00000000"));
    CHECK_EQ(written_line(nearly, nearly, nearly, 1.0, 20.0, NumberFormat::fixed8),
             std::string("3 0 0.00000000 0.00000000 20.00000000 1.00000000\n"));
    CHECK_EQ(written_line(nearly, 5.0, 0.0, 0.0, 0.0, NumberFormat::fixed8),
             std::string("3 0 20.00000000 5.00000000 0.00000000 0.00000000\n"));  // walls: as printed
    CHECK_EQ(written_line(19.99999999, 0.0, 0.0, 0.0, 20.0, NumberFormat::fixed8),
             std::string("3 0 19.99999999 0.00000000 0.00000000 0.00000000\n"));
    CHECK_EQ(written_line(nearly, 5.0, 0.0, 0.0, 20.0, NumberFormat::shortest),
             std::string("3 0 19.9999999996 5 0 0\n"));  // the shortest form reads back below 20
    // Every double just below the side, for sides that are and are not 8-decimal numbers.
    for (const double side : {20.0, 0.1, 1.0 / 3.0, 12345.678901234, 1e12}) {
        double x = side;
        for (int k = 0; k < 200; ++k) {
            x = std::nextafter(x, 0.0);
            const std::string line = written_line(x, 1e-3, 0.0, 0.0, side, NumberFormat::fixed8);
            const double printed = std::strtod(line.c_str() + 4, nullptr);
            check::Context context("side ", side, ", x ", x, ": ", line);
            CHECK(printed >= 0.0 && printed < side);
            CHECK(line.substr(4, reference(x).size()) == reference(x) || printed == 0.0);
        }
    }
    for (const double side : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
        std::string why;
        try {
            StateWriter(stdout).wrap_positions_into(side);
        } catch (const std::invalid_argument& e) {
            why = e.what();
        }
        CHECK(why.rfind("particlesim::StateWriter::wrap_positions_into: the side must be finite and positive", 0) == 0);
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_number_format",
        {{"fixed and short formats",
          [] {
              // Hand-picked: zeros, ties of the 8th decimal (exact binary halves),
              // carries, negatives that round to zero, large and huge magnitudes.
              const double cases[] = {0.0,
                                      -0.0,
                                      1.0,
                                      -1.0,
                                      0.5,
                                      0x1p-9,
                                      0x1p-30,
                                      0.000000005,
                                      0.000000015,
                                      -0.000000004,
                                      -0.000000005,
                                      0.999999995,
                                      9.999999995,
                                      19999.0,
                                      20000.0 - 1e-12,
                                      1e15 + 0.5,
                                      0x1p52,
                                      0x1p53 + 2,
                                      1e150,
                                      -1e150,
                                      123456.123456789,
                                      3.0000000049999999};
              for (const double value : cases) CHECK_EQ(fast(value), reference(value));
              CHECK_EQ(fast(-0.0), std::string("0.00000000"));
              CHECK_EQ(fast(-0.000000001), std::string("0.00000000"));

              // Random values over many scales, and values with few binary digits (the
              // ones that produce exact ties).
              SplitMix64 rng(7);
              int mismatches = 0;
              for (int k = 0; k < 400000; ++k) {
                  const double scale = std::ldexp(1.0, static_cast<int>(rng.next() % 80) - 30);
                  double value = (rng.uniform() - 0.5) * scale;
                  if (k % 4 == 0)
                      value = std::ldexp(std::round(value * 1024.0), -10 - static_cast<int>(rng.next() % 30));
                  if (fast(value) != reference(value)) ++mismatches;
              }
              CHECK_EQ(mismatches, 0);
          }},
         // Every finite double, from the smallest subnormal to
         // DBL_MAX (309 integer digits), as printf writes it, never a NUL byte.
         {"every finite double",
          [] {
              const double extremes[] = {std::numeric_limits<double>::max(),
                                         -std::numeric_limits<double>::max(),
                                         std::numeric_limits<double>::denorm_min(),
                                         -std::numeric_limits<double>::min(),
                                         1e303,
                                         -2.5e303,
                                         1e60,
                                         1e-60};
              for (const double value : extremes) {
                  const std::string text = fast(value);
                  CHECK_EQ(text, reference(value));
                  CHECK(text.find('\0') == std::string::npos);
              }
              SplitMix64 rng(11);
              int mismatches = 0;
              for (int k = 0; k < 20000; ++k) {
                  const double value = std::ldexp(rng.uniform() - 0.5, static_cast<int>(rng.next() % 2100) - 1075);
                  if (std::isfinite(value) && fast(value) != reference(value)) ++mismatches;
              }
              CHECK_EQ(mismatches, 0);
              char text[40];
              for (const double value : {0.1, -0.0, 1e-310, 1.7976931348623157e308, -2.5e-60}) {
                  const std::string shortest(text, write_shortest(text, value));
                  CHECK_EQ(std::strtod(shortest.c_str(), nullptr), value);
                  CHECK(shortest.size() <= 24);
              }
          }},
         {"positions wrapped into a periodic box", positions_wrapped_into_a_periodic_box}});
}
