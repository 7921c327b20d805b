#pragma once
// A quantity known only within bounds: the closed interval [lo, hi] holds its
// exact value for every input inside the inputs' bounds, and also the value
// any reasonable program computes for it. Each operation therefore widens its
// result by a formula allowance (a few hundred units in the last place of the
// operands): two correct programs may order their roundings differently, or
// use a unit normal where we do not. An operation on exact operands whose
// result is exact (checked with error-free transformations) stays exact, so
// ties built from small dyadic numbers stay ties for every formula.
// The step checker (step_check.cpp) evaluates the step rules with it.

#include "core/double_double.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace particlesim {

// Three-valued truth of a decision of the rules under uncertainty.
enum class Tri { no, maybe, yes };

inline Tri tri_and(Tri a, Tri b) { return std::min(a, b); }
inline Tri tri_or(Tri a, Tri b) { return std::max(a, b); }

struct Uncertain {
    // How far another correct formula may land from ours, relative to the
    // operands: 2^-48, 32 units in the last place (a formula of a dozen
    // operations, each off by at most half a unit, in whatever order).
    static constexpr double formula_allowance = 0x1p-48;

    double lo = 0.0;
    double hi = 0.0;

    static Uncertain exact(double value) { return {value, value}; }
    static Uncertain around(double value, double radius) { return {value - radius, value + radius}; }
    static Uncertain everything() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    }

    [[nodiscard]] bool is_exact() const { return lo == hi; }
    [[nodiscard]] double mid() const { return is_exact() ? lo : lo + 0.5 * (hi - lo); }
    [[nodiscard]] double magnitude() const { return std::max(std::fabs(lo), std::fabs(hi)); }
    [[nodiscard]] bool contains(double value, double tolerance) const {
        return lo - tolerance <= value && value <= hi + tolerance;
    }

    [[nodiscard]] Tri below_or_at(double limit) const {
        return hi <= limit ? Tri::yes : (lo > limit ? Tri::no : Tri::maybe);
    }
    [[nodiscard]] Tri below(double limit) const { return hi < limit ? Tri::yes : (lo >= limit ? Tri::no : Tri::maybe); }
    [[nodiscard]] Tri above(double limit) const { return lo > limit ? Tri::yes : (hi <= limit ? Tri::no : Tri::maybe); }

    // The bounds [lo, hi] computed in double, widened by the allowance
    // relative to `scale` (the largest operand or result).
    // A NaN bound (an infinite bound times zero) means nothing is known.
    static Uncertain widened(double lo, double hi, double scale) {
        if (std::isnan(lo) || std::isnan(hi) || std::isnan(scale)) return everything();
        const double allowance = formula_allowance * scale + std::numeric_limits<double>::denorm_min();
        return {lo - allowance, hi + allowance};
    }
};

inline Uncertain hull(const Uncertain& a, const Uncertain& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

// The part of `a` inside [lower, upper] (a value known to lie there).
inline Uncertain clamped(const Uncertain& a, double lower, double upper) {
    return {std::clamp(a.lo, lower, upper), std::clamp(a.hi, lower, upper)};
}

inline Uncertain operator-(const Uncertain& a) { return {-a.hi, -a.lo}; }

inline Uncertain operator+(const Uncertain& a, const Uncertain& b) {
    if (a.is_exact() && b.is_exact()) {
        const DoubleDouble sum = two_sum(a.lo, b.lo);
        if (sum.lo == 0.0) return Uncertain::exact(sum.hi);
    }
    const double scale = std::max({a.magnitude(), b.magnitude(), std::fabs(a.hi + b.hi), std::fabs(a.lo + b.lo)});
    return Uncertain::widened(a.lo + b.lo, a.hi + b.hi, scale);
}

inline Uncertain operator-(const Uncertain& a, const Uncertain& b) { return a + -b; }

inline bool is_exact_zero(const Uncertain& a) { return a.lo == 0.0 && a.hi == 0.0; }

inline Uncertain operator*(const Uncertain& a, const Uncertain& b) {
    // Every formula gives 0 * x = 0 exactly (x is bounded).
    if ((is_exact_zero(a) && std::isfinite(b.magnitude())) || (is_exact_zero(b) && std::isfinite(a.magnitude()))) {
        return Uncertain::exact(0.0);
    }
    if (a.is_exact() && b.is_exact()) {
        const DoubleDouble product = two_product(a.lo, b.lo);
        if (product.lo == 0.0) return Uncertain::exact(product.hi);
    }
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    const double lo = std::min({p1, p2, p3, p4});
    const double hi = std::max({p1, p2, p3, p4});
    return Uncertain::widened(lo, hi, std::max(std::fabs(lo), std::fabs(hi)));
}

// Unbounded when the divisor may be zero.
inline Uncertain operator/(const Uncertain& a, const Uncertain& b) {
    if (b.lo <= 0.0 && b.hi >= 0.0) return Uncertain::everything();
    if (is_exact_zero(a)) return Uncertain::exact(0.0);
    if (a.is_exact() && b.is_exact()) {
        const double quotient = a.lo / b.lo;
        const DoubleDouble back = two_product(quotient, b.lo);
        if (back.hi == a.lo && back.lo == 0.0) return Uncertain::exact(quotient);
    }
    const double q1 = a.lo / b.lo, q2 = a.lo / b.hi, q3 = a.hi / b.lo, q4 = a.hi / b.hi;
    const double lo = std::min({q1, q2, q3, q4});
    const double hi = std::max({q1, q2, q3, q4});
    return Uncertain::widened(lo, hi, std::max(std::fabs(lo), std::fabs(hi)));
}

// Of the non-negative part of `a`.
inline Uncertain sqrt_of(const Uncertain& a) {
    const double lo = std::sqrt(std::max(a.lo, 0.0));
    const double hi = std::sqrt(std::max(a.hi, 0.0));
    if (a.is_exact()) {
        const DoubleDouble back = two_product(lo, lo);
        if (back.hi == std::max(a.lo, 0.0) && back.lo == 0.0) return Uncertain::exact(lo);
    }
    const Uncertain widened = Uncertain::widened(lo, hi, hi);
    return {std::max(widened.lo, 0.0), widened.hi};
}

// a * a, which is never negative (a * b of the same interval could be).
inline Uncertain square(const Uncertain& a) {
    if (a.lo >= 0.0 || a.hi <= 0.0 || a.is_exact()) {
        const Uncertain product = a * a;
        return {std::max(product.lo, 0.0), product.hi};
    }
    const double hi = std::max(a.lo * a.lo, a.hi * a.hi);
    return {0.0, Uncertain::widened(hi, hi, hi).hi};
}

inline Uncertain min_of(const Uncertain& a, const Uncertain& b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }

}  // namespace particlesim
