// On many random scenes, after every step: every centre inside [r, L - r]
// exactly, all numbers finite, kinetic energy conserved to rounding, and the
// counters consistent with the collisions the step reported.

#include "check.hpp"
#include "random_scenes.hpp"

#include "core/physics.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <cmath>

using namespace particlesim;

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_invariants",
        {{"invariants on random scenes", [] {
              int outside = 0;
              int non_finite = 0;
              int energy_drift = 0;
              int counter_mismatch = 0;
              for (std::uint64_t k = 0; k < 60; ++k) {
                  const NamedScene scene = random_scenes::make(k);
                  SteppedSimulation sim(scene.world, scene.particles);
                  double initial_energy = 0.0;
                  for (const Particle& p : sim.particles()) initial_energy += kinetic_energy(p);
                  std::uint64_t counted_pc = 0;
                  std::uint64_t counted_wc = 0;
                  particlesim::run(sim, scene.steps, [&](std::int64_t, std::span<const Particle> particles) {
                      double energy = 0.0;
                      std::uint64_t pc = 0;
                      std::uint64_t wc = 0;
                      for (const Particle& p : particles) {
                          const bool in =
                              p.position.x() >= scene.world.lower() && p.position.x() <= scene.world.upper() &&
                              p.position.y() >= scene.world.lower() && p.position.y() <= scene.world.upper();
                          outside += in ? 0 : 1;
                          non_finite += p.position.allFinite() && p.velocity.allFinite() ? 0 : 1;
                          energy += kinetic_energy(p);
                          pc += p.particle_collisions;
                          wc += p.wall_collisions;
                      }
                      counted_pc += 2 * sim.last_step().particle_collisions;
                      counted_wc += sim.last_step().wall_collisions;
                      counter_mismatch += pc == counted_pc && wc == counted_wc ? 0 : 1;
                      if (std::fabs(energy - initial_energy) > 1e-12 * initial_energy) ++energy_drift;
                  });
              }
              CHECK_EQ(outside, 0);
              CHECK_EQ(non_finite, 0);
              CHECK_EQ(energy_drift, 0);
              CHECK_EQ(counter_mismatch, 0);
          }}});
}
