#pragma once
// What a researcher measures on hard disks: the pressure from the
// collisions themselves (two routes in a walled box), the global hexatic
// order, and a mean with its error bar from block averages.
//
// Conventions (docs/physics.md): mass 1; in a walled box the centres move in
// the square of side L - 2r, whose area A = (L - 2r)^2 enters both routes, and
// total momentum is not conserved (the walls take it), so all 2N degrees of
// freedom are thermal: kT = E_kin / N. In a periodic box A = L^2 and the
// total momentum P is conserved: the centre of mass's motion is not thermal,
// and kT = (E_kin - |P|^2 / 2N) / (N - 1), the same for a box that drifts.

#include "particlesim/particle.hpp"
#include "particlesim/world.hpp"

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace particlesim {

// What the collisions carried, summed since the engine started.
struct CollisionSums {
    double pair_virial = 0.0;   // over pair collisions, r_ij . dp_i (i's change of momentum, r_ij = r_i - r_j)
    double wall_impulse = 0.0;  // over wall collisions, |dp| (the momentum the walls took)

    CollisionSums operator-(const CollisionSums& earlier) const {
        return {pair_virial - earlier.pair_virial, wall_impulse - earlier.wall_impulse};
    }
};

// The pressure over an interval of `duration` (steps) in which the
// collisions carried `sums`, for `count` disks with kinetic energy
// `kinetic_energy`, as beta P (2r)^2 and Z = beta P A / N:
//   virial: P A = N kT + sum(r_ij . dp_i) / (2 duration)
//   walls:  P = sum |dp| / (duration x 4 (L - 2r))
// Both are the same pressure (the virial theorem with the walls' forces);
// they differ only by the noise of a finite interval. All zero, kT too, where
// there is nothing to measure: no interval (duration not above 0), no disk
// (fewer than two in a periodic box, whose kT counts N - 1), no kinetic
// energy (in a periodic box: none beside the centre of mass's), or no room
// for the centres (2r = L). Throws std::invalid_argument for a world the
// engines refuse (L or r outside the accepted range of world.hpp, or 2r > L)
// and a kinetic energy that is negative or not finite; the periodic box also
// for a total momentum that is not finite or whose energy |P|^2 / 2N exceeds
// the kinetic energy (not these disks').
struct Pressure {
    double kT = 0.0;
    double betaP_d2 = 0.0;  // virial route
    double Z = 0.0;
    double betaP_d2_walls = 0.0;
    double Z_walls = 0.0;
};
Pressure walled_box_pressure(const World& world, std::size_t count, double kinetic_energy, const CollisionSums& sums,
                             double duration);

// The same in a periodic box (ExactOptions::boundary): the virial route
// alone (no walls; the walls' fields stay 0), with A = L^2 and, as the total
// momentum (`total_momentum`, conserved) is not thermal,
// kT = (E_kin - |P|^2 / 2N) / (N - 1): the state in its centre of mass's frame.
Pressure periodic_box_pressure(const World& world, std::size_t count, double kinetic_energy, const Vec2& total_momentum,
                               const CollisionSums& sums, double duration);

// The one of the two above that the boundary calls for (std::invalid_argument
// for a Boundary that names neither box); the walled box ignores the
// momentum, which its walls do not conserve.
Pressure box_pressure(const World& world, Boundary boundary, std::size_t count, double kinetic_energy,
                      const Vec2& total_momentum, const CollisionSums& sums, double duration);

// The sum of the particles' velocities (mass 1), for the periodic box's kT.
Vec2 total_momentum(std::span<const Particle> particles);

// |<psi6>|: the mean over disks of (1/6) sum over its six nearest neighbours
// of exp(6 i theta), theta the bond's angle. Six nearest rather than Voronoi
// neighbours: no tessellation to build, the same count at every disk (a
// Voronoi cell of a dense liquid often has five or seven), and the common
// choice of the hard-disk papers' quick estimates; of neighbours at equal
// distance (a square lattice's second shell), the lower indices. The search
// refines its cells where disks crowd, so that a cluster in an empty box
// costs about what a spread does. 1 on a perfect triangular lattice, about
// 1 / sqrt(N) for a random gas. 0 for fewer than 7 disks. In a
// periodic box, neighbours are nearest images, and a position may lie whole
// sides outside the box (unwrapped coordinates). Throws std::invalid_argument
// for a position that is not a finite number, a box size that is not finite
// and positive, or a Boundary that names neither box.
double hexatic_order(std::span<const Particle> particles, const World& world, Boundary boundary = Boundary::walls);

// Each disk's own psi6, (1/6) sum over its six nearest neighbours of
// exp(6 i theta), by index: its phase arg(psi6) / 6 is the local lattice's
// orientation (the picture of hexatic domains), its modulus how ordered the
// neighbourhood is. hexatic_order() is |the mean of these|. All 0 for fewer
// than 7 disks.
std::vector<std::complex<double>> local_hexatic_order(std::span<const Particle> particles, const World& world,
                                                      Boundary boundary = Boundary::walls);

// |the mean of the disks' own psi6|: hexatic_order() from what
// local_hexatic_order() gave, for a caller that has both to show. 0 for
// fewer than 7 disks.
double mean_hexatic_order(std::span<const std::complex<double>> local);

// The mean of a series and its standard error from `blocks` block averages
// (the error of correlated samples: blocks longer than the correlation time
// are independent), for samples of any finite magnitude. Needs at least 2
// samples a block: fewer samples give error 0 and blocks 0.
struct MeanWithError {
    double mean = 0.0;
    double error = 0.0;
    std::size_t blocks = 0;
};
MeanWithError block_average(std::span<const double> samples, std::size_t blocks = 16);

}  // namespace particlesim
