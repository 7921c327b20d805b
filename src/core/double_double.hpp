#pragma once
// Unevaluated sums hi + lo of two doubles (about 106 bits), built only on
// IEEE operations that every conforming machine rounds identically: +, -, *
// and /. So a result computed with them is the same double on x86-64, aarch64
// and everywhere else, which `long double` (80, 128 or 64 bits depending on
// the platform) is not.
// Needs -ffp-contract=off, which the library is built with.

namespace particlesim {

// Real is double, or a vector of doubles (GCC's vector extension) whose every
// lane carries out the same operations as a double would: the same bits.
template <typename Real>
struct DoubleDoubleOf {
    Real hi{};
    Real lo{};
};
using DoubleDouble = DoubleDoubleOf<double>;

// a + b exactly (Knuth's TwoSum).
template <typename Real>
inline DoubleDoubleOf<Real> two_sum(Real a, Real b) {
    const Real sum = a + b;
    const Real b_part = sum - a;
    const Real a_part = sum - b_part;
    return {sum, (a - a_part) + (b - b_part)};
}

// The high and low halves of a double, 26 bits each (Veltkamp's split).
template <typename Real>
inline DoubleDoubleOf<Real> split(Real a) {
    constexpr double splitter = 134217729.0;  // 2^27 + 1
    const Real scaled = splitter * a;
    const Real high = scaled - (scaled - a);
    return {high, a - high};
}

// a * b exactly (Dekker's product), barring overflow and underflow, which the
// accepted range excludes (docs/accepted-range.md). The same bits as
// std::fma(a, b, -a * b), without a call into libm on machines whose
// baseline has no fused multiply-add.
template <typename Real>
inline DoubleDoubleOf<Real> two_product(Real a, Real b) {
    const Real product = a * b;
    const DoubleDoubleOf<Real> x = split(a);
    const DoubleDoubleOf<Real> y = split(b);
    const Real error = ((x.hi * y.hi - product) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo;
    return {product, error};
}

template <typename Real>
inline DoubleDoubleOf<Real> renormalized(Real hi, Real lo) {
    const Real sum = hi + lo;
    return {sum, lo - (sum - hi)};
}

template <typename Real>
inline DoubleDoubleOf<Real> operator+(const DoubleDoubleOf<Real>& a, const DoubleDoubleOf<Real>& b) {
    const DoubleDoubleOf<Real> high = two_sum(a.hi, b.hi);
    const DoubleDoubleOf<Real> low = two_sum(a.lo, b.lo);
    const DoubleDoubleOf<Real> partial = renormalized(high.hi, high.lo + low.hi);
    return renormalized(partial.hi, partial.lo + low.lo);
}

template <typename Real>
inline DoubleDoubleOf<Real> operator-(const DoubleDoubleOf<Real>& a) {
    return {-a.hi, -a.lo};
}

template <typename Real>
inline DoubleDoubleOf<Real> operator*(const DoubleDoubleOf<Real>& a, const DoubleDoubleOf<Real>& b) {
    const DoubleDoubleOf<Real> high = two_product(a.hi, b.hi);
    return renormalized(high.hi, high.lo + (a.hi * b.lo + a.lo * b.hi));
}

template <typename Real>
inline DoubleDoubleOf<Real> operator/(const DoubleDoubleOf<Real>& a, const DoubleDoubleOf<Real>& b) {
    // One Newton correction of the double quotient: q + (a - q b) / b.
    const Real quotient = a.hi / b.hi;
    const DoubleDoubleOf<Real> remainder = a + -(DoubleDoubleOf<Real>{quotient, Real{}} * b);
    const Real correction = (remainder.hi + remainder.lo) / b.hi;
    return renormalized(quotient, correction);
}

// The double nearest to a + b (up to the last of ~106 bits).
template <typename Real>
inline Real rounded_sum(Real a, const DoubleDoubleOf<Real>& b) {
    const DoubleDoubleOf<Real> high = two_sum(a, b.hi);
    return high.hi + (high.lo + b.lo);
}

}  // namespace particlesim
