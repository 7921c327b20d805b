// write_fixed8 must print exactly what printf("%.8f") prints (but for -0), for
// every finite double; write_shortest must read back to the same double.

#include "check.hpp"

#include "core/random.hpp"
#include "io/number_format.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

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
         {"every finite double", [] {
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
          }}});
}
