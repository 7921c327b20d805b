#pragma once
// The line test in float that the paths search and the grid search share:
// two particles' separation moves along a line, so they come within `reach`
// of each other only if |dp x dv| <= reach |dv|, whatever the time. In
// float lanes it reads
//
//     |dp x dv|^2 <= reach_term |dv|^2 + margin_term
//
// with positions and velocities scaled so that nothing overflows in float
// (the grid's by powers of two, exactly, the largest about 1; the paths
// search's positions so that the scaled reach is about 1), and the two terms
// below widening the test past every rounding: a pair that the
// double-precision tests would find always passes; a few more do.

#include <cmath>

namespace particlesim {

// 2^-k with value * 2^-k in [0.5, 1); 1 for zero (or anything not finite,
// which valid scenes never hold).
inline double power_of_two_below(double value) {
    if (!(value > 0.0 && std::isfinite(value))) return 1.0;
    return std::ldexp(1.0, -(std::ilogb(value) + 1));
}

struct LineTerms {
    float reach_term;   // times |dv|^2
    float margin_term;  // added
};

// One particle's line in float: position and velocity, scaled.
struct FloatLine {
    float x, y, vx, vy;
};

// The two sides of the test, lane by lane, for `Floats` stored lines (a
// vector of four, eight or sixteen floats each component) against `line`:
// |dp x dv|^2 and reach_term |dv|^2 + margin_term (the grid search's).
// Written once, so that a line passes the same way in every block and lane
// width. Vectors
// go by reference only: a wider one passed or returned by value would
// change the calling convention of a build without AVX.
template <typename Floats>
[[gnu::always_inline]] inline void line_test_sides(const Floats& x, const Floats& y, const Floats& vx, const Floats& vy,
                                                   const FloatLine& line, const LineTerms& terms, Floats& cross_sq,
                                                   Floats& bound) {
    const Floats dx = x - line.x;
    const Floats dy = y - line.y;
    const Floats dvx = vx - line.vx;
    const Floats dvy = vy - line.vy;
    const Floats cross = dx * dvy - dy * dvx;
    const Floats speed_sq = dvx * dvx + dvy * dvy;
    cross_sq = cross * cross;
    bound = terms.reach_term * speed_sq + terms.margin_term;
}

// The same test for lines whose positions are scaled so that reach_term is
// at most 1 (PathLines): |dp x dv|^2 <= |dv|^2 + margin_term, one
// multiplication a line fewer. Passing line_test_sides() implies passing
// this one (a larger factor of |dv|^2), so it keeps every pair that one keeps.
template <typename Floats>
[[gnu::always_inline]] inline void unit_reach_line_test_sides(const Floats& x, const Floats& y, const Floats& vx,
                                                              const Floats& vy, const FloatLine& line,
                                                              const LineTerms& terms, Floats& cross_sq, Floats& bound) {
    const Floats dx = x - line.x;
    const Floats dy = y - line.y;
    const Floats dvx = vx - line.vx;
    const Floats dvy = vy - line.vy;
    const Floats cross = dx * dvy - dy * dvx;
    cross_sq = cross * cross;
    bound = dvx * dvx + (dvy * dvy + terms.margin_term);
}

// For scaled coordinates of at most `largest_coordinate` (M) and velocity
// components of at most `largest_speed` (V), and a scaled reach.
//
// Rounding each scaled value to float moves it by at most 2^-24 of M or V
// (2^-52 of M more where the scale is no power of two: within the slack);
// the differences, products and sum of the cross product then err by less
// than 64 * 2^-24 M V, and the computed |dv| by less than 6 * 2^-24 V. With
// (a + b)^2 <= 1.25 a^2 + 5 b^2, and slack for the three float roundings of
// the comparison (a fused multiply-add only rounds less):
inline LineTerms line_test_terms(double largest_coordinate, double largest_speed, double reach_scaled) {
    const double error =
        128.0 * 0x1p-24 * largest_coordinate * largest_speed + 12.0 * 0x1p-24 * reach_scaled * largest_speed;
    return {static_cast<float>(1.3 * reach_scaled * reach_scaled), static_cast<float>(6.0 * error * error)};
}

}  // namespace particlesim
