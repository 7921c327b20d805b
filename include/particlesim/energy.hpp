#pragma once
// Total kinetic energy at full precision: a compensated (Neumaier) sum, so
// that a drift of 1e-15 is a property of the dynamics, not of the summation.

#include "particlesim/particle.hpp"
#include "particlesim/physics.hpp"

#include <cmath>
#include <span>

namespace particlesim {

inline double total_kinetic_energy(std::span<const Particle> particles) {
    double sum = 0.0;
    double compensation = 0.0;
    for (const Particle& p : particles) {
        const double term = kinetic_energy(p);
        const double next = sum + term;
        compensation += std::abs(sum) >= std::abs(term) ? (sum - next) + term : (term - next) + sum;
        sum = next;
    }
    return sum + compensation;
}

// (E - E0) / E0, or 0 when there was no energy to begin with.
inline double relative_energy_drift(double initial, double current) {
    return initial > 0.0 ? (current - initial) / initial : 0.0;
}

}  // namespace particlesim
