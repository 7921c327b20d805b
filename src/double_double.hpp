#pragma once
// Unevaluated sums hi + lo of two doubles (about 106 bits), built only on
// IEEE operations that every conforming machine rounds identically: +, -, *
// and /. So a result computed with them is the same double on x86-64, aarch64
// and everywhere else, which `long double` (80, 128 or 64 bits depending on
// the platform) is not.
// Needs -ffp-contract=off, which the library is built with.

namespace particlesim {

struct DoubleDouble {
    double hi = 0.0;
    double lo = 0.0;
};

// a + b exactly (Knuth's TwoSum).
inline DoubleDouble two_sum(double a, double b) {
    const double sum = a + b;
    const double b_part = sum - a;
    const double a_part = sum - b_part;
    return {sum, (a - a_part) + (b - b_part)};
}

// The high and low halves of a double, 26 bits each (Veltkamp's split).
inline DoubleDouble split(double a) {
    constexpr double splitter = 134217729.0;  // 2^27 + 1
    const double scaled = splitter * a;
    const double high = scaled - (scaled - a);
    return {high, a - high};
}

// a * b exactly (Dekker's product), barring overflow and underflow, which the
// accepted range excludes (docs/accepted-range.md). The same bits as
// std::fma(a, b, -a * b), without a call into libm on machines whose
// baseline has no fused multiply-add.
inline DoubleDouble two_product(double a, double b) {
    const double product = a * b;
    const DoubleDouble x = split(a);
    const DoubleDouble y = split(b);
    const double error = ((x.hi * y.hi - product) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo;
    return {product, error};
}

inline DoubleDouble renormalized(double hi, double lo) {
    const double sum = hi + lo;
    return {sum, lo - (sum - hi)};
}

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
    const DoubleDouble high = two_sum(a.hi, b.hi);
    const DoubleDouble low = two_sum(a.lo, b.lo);
    const DoubleDouble partial = renormalized(high.hi, high.lo + low.hi);
    return renormalized(partial.hi, partial.lo + low.lo);
}

inline DoubleDouble operator-(const DoubleDouble& a) { return {-a.hi, -a.lo}; }

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
    const DoubleDouble high = two_product(a.hi, b.hi);
    return renormalized(high.hi, high.lo + (a.hi * b.lo + a.lo * b.hi));
}

inline DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
    // One Newton correction of the double quotient: q + (a - q b) / b.
    const double quotient = a.hi / b.hi;
    const DoubleDouble remainder = a + -(DoubleDouble{quotient, 0.0} * b);
    const double correction = (remainder.hi + remainder.lo) / b.hi;
    return renormalized(quotient, correction);
}

// The double nearest to a + b (up to the last of ~106 bits).
inline double rounded_sum(double a, const DoubleDouble& b) {
    const DoubleDouble high = two_sum(a, b.hi);
    return high.hi + (high.lo + b.lo);
}

}  // namespace particlesim
