#pragma once
// A small, fully specified random generator (SplitMix64) and our own mapping
// of its bits to doubles, so that a seed gives the same scene on every
// platform and standard library (std:: distributions differ between them).

#include "particlesim/particle.hpp"

#include <cmath>
#include <cstdint>

namespace particlesim {

class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    // Uniform in [0, 1): the top 53 bits, exactly representable.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

private:
    std::uint64_t state_;
};

// A direction uniform in [0, 2 pi): a point drawn uniformly in the unit disk,
// normalised. No trigonometry, so the same on every IEEE-754 platform.
inline Vec2 random_direction(SplitMix64& rng) {
    for (;;) {
        const double x = 2.0 * rng.uniform() - 1.0;
        const double y = 2.0 * rng.uniform() - 1.0;
        const double norm_sq = x * x + y * y;
        if (norm_sq <= 1.0 && norm_sq > 1e-12) return Vec2(x, y) / std::sqrt(norm_sq);
    }
}

}  // namespace particlesim
