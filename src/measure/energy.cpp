#include "core/physics.hpp"
#include "particlesim/accuracy.hpp"

#include <cmath>

namespace particlesim {

// A compensated (Neumaier) sum, so that the drift it shows is a property of
// the dynamics, not of the summation.
double total_kinetic_energy(std::span<const Particle> particles) {
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

double relative_energy_drift(double initial, double current) {
    return initial > 0.0 ? (current - initial) / initial : 0.0;
}

}  // namespace particlesim
