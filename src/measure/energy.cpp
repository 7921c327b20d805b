#include "core/physics.hpp"
#include "particlesim/accuracy.hpp"

#include <cmath>

namespace particlesim {

// A compensated (Neumaier) sum, so that the drift it shows is a property of
// the dynamics, not of the summation.
void KineticEnergySum::add(std::span<const Particle> particles) {
    for (const Particle& p : particles) {
        const double term = kinetic_energy(p);
        const double next = sum_ + term;
        compensation_ += std::abs(sum_) >= std::abs(term) ? (sum_ - next) + term : (term - next) + sum_;
        sum_ = next;
    }
}

double total_kinetic_energy(std::span<const Particle> particles) {
    KineticEnergySum sum;
    sum.add(particles);
    return sum.total();
}

double relative_energy_drift(double initial, double current) {
    return initial > 0.0 ? (current - initial) / initial : 0.0;
}

}  // namespace particlesim
