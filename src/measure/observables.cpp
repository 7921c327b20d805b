#include "particlesim/observables.hpp"

#include "core/crowded_grid.hpp"
#include "core/physics.hpp"
#include "core/points_by_cell.hpp"
#include "core/uniform_grid.hpp"
#include "input/options_check.hpp"
#include "input/scene_checks.hpp"
#include "io/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace particlesim {

namespace {

// psi6's neighbour grid: refined while a disk's mean count of cell mates
// passes this, up to this many cells a disk (a cluster of 200 000 disks in an
// empty box took 12 to 13 s a search in cells of about four disks each, 0.5 s
// so refined; 64 cells a disk took longer, clearing and faulting in cells).
constexpr double psi6_most_cell_mates = 16.0;
constexpr double psi6_most_cells_per_disk = 16.0;
constexpr double psi6_most_cells_a_side = 4096.0;  // 64 MiB of counts at most

// What both boxes report of a pressure P: beta P (2r)^2 and Z = beta P A / N.
struct Reported {
    double betaP_d2;
    double Z;
};
Reported reported(double pressure, double kT, double area, double n, const World& world) {
    return {pressure / kT * (4.0 * world.radius * world.radius), pressure * area / (n * kT)};
}

// The virial route: P A = N kT + sum(r_ij . dp_i) / (2 duration).
double virial_pressure(double n, double kT, double area, const CollisionSums& sums, double duration) {
    return (n * kT + sums.pair_virial / (2.0 * duration)) / area;
}

// What a pressure needs: a world the engines accept (the same check), and a
// kinetic energy that is one (finite, not negative).
void require_pressure_inputs(const char* function, const World& world, double kinetic_energy) {
    require_valid_scene(function, world, {});
    if (!(std::isfinite(kinetic_energy) && kinetic_energy >= 0.0)) {
        OptionsCheck(function).fail("the kinetic energy must be finite and not negative, not " +
                                    format_short(kinetic_energy));
    }
}

// What a psi6 search needs: a box it can bin, and positions it can place.
void require_measurable(std::span<const Particle> particles, const World& world, Boundary boundary) {
    const OptionsCheck check("particlesim::local_hexatic_order");
    check.known_boundary("boundary", boundary);
    if (!(std::isfinite(world.box_size) && world.box_size > 0.0))
        check.fail("the box size must be finite and positive, not " + format_short(world.box_size));
    for (std::size_t k = 0; k < particles.size(); ++k) {
        const Vec2& at = particles[k].position;
        if (!std::isfinite(at.x()) || !std::isfinite(at.y()))
            check.fail("particle " + std::to_string(k) + "'s position is not a finite number");
    }
}

}  // namespace

Pressure walled_box_pressure(const World& world, std::size_t count, double kinetic_energy, const CollisionSums& sums,
                             double duration) {
    require_pressure_inputs("particlesim::walled_box_pressure", world, kinetic_energy);
    Pressure p;
    if (count == 0 || !(duration > 0.0)) return p;
    const double n = static_cast<double>(count);
    const double side = world.box_size - 2.0 * world.radius;
    const double area = side * side;
    if (!(kinetic_energy > 0.0) || !(area > 0.0)) return p;
    p.kT = kinetic_energy / n;
    const Reported virial = reported(virial_pressure(n, p.kT, area, sums, duration), p.kT, area, n, world);
    const Reported walls = reported(sums.wall_impulse / (duration * 4.0 * side), p.kT, area, n, world);
    p.betaP_d2 = virial.betaP_d2;
    p.Z = virial.Z;
    p.betaP_d2_walls = walls.betaP_d2;
    p.Z_walls = walls.Z;
    return p;
}

Pressure periodic_box_pressure(const World& world, std::size_t count, double kinetic_energy, const Vec2& total_momentum,
                               const CollisionSums& sums, double duration) {
    const char* const function = "particlesim::periodic_box_pressure";
    require_pressure_inputs(function, world, kinetic_energy);
    const OptionsCheck check(function);
    if (!std::isfinite(total_momentum.x()) || !std::isfinite(total_momentum.y())) {
        check.fail("the total momentum must be finite, not (" + format_short(total_momentum.x()) + ", " +
                   format_short(total_momentum.y()) + ")");
    }
    Pressure p;
    if (count < 2 || !(duration > 0.0)) return p;
    const double n = static_cast<double>(count);
    const double area = world.box_size * world.box_size;
    const double centre_of_mass_energy = total_momentum.squaredNorm() / (2.0 * n);
    // |P|^2 / 2N <= E_kin for any N velocities (Cauchy-Schwarz); summing N
    // terms rounds by about N units in the last place, far below 1e-6 of it.
    if (centre_of_mass_energy > kinetic_energy * (1.0 + 1e-6)) {
        check.fail("the total momentum's energy |P|^2 / 2N = " + format_short(centre_of_mass_energy) +
                   " exceeds the kinetic energy " + format_short(kinetic_energy) + ": not the momentum of these " +
                   std::to_string(count) + " disks");
    }
    const double thermal_kT = (kinetic_energy - centre_of_mass_energy) / (n - 1.0);
    if (!(thermal_kT > 0.0)) return p;  // a box that only drifts (or rounding of one): nothing to measure
    p.kT = thermal_kT;
    const Reported virial = reported(virial_pressure(n, p.kT, area, sums, duration), p.kT, area, n, world);
    p.betaP_d2 = virial.betaP_d2;
    p.Z = virial.Z;
    return p;
}

Pressure box_pressure(const World& world, Boundary boundary, std::size_t count, double kinetic_energy,
                      const Vec2& total_momentum, const CollisionSums& sums, double duration) {
    OptionsCheck("particlesim::box_pressure").known_boundary("boundary", boundary);
    return boundary == Boundary::periodic
               ? periodic_box_pressure(world, count, kinetic_energy, total_momentum, sums, duration)
               : walled_box_pressure(world, count, kinetic_energy, sums, duration);
}

Vec2 total_momentum(std::span<const Particle> particles) {
    Vec2 sum = Vec2::Zero();
    for (const Particle& p : particles) sum += p.velocity;
    return sum;
}

std::vector<std::complex<double>> local_hexatic_order(std::span<const Particle> particles, const World& world,
                                                      Boundary boundary) {
    require_measurable(particles, world, boundary);
    const std::size_t n = particles.size();
    std::vector<std::complex<double>> local(n, std::complex<double>(0.0, 0.0));
    if (n < 7) return local;
    const bool periodic = boundary == Boundary::periodic;
    const double side = world.box_size;
    // In a periodic box a disk is binned where it is inside the box: a
    // caller's unwrapped coordinates (whole sides away) are the same disks.
    const auto in_box = [&](double c) { return periodic ? wrap_into_periodic_box(c, side) : c; };
    const auto binned_at = [&](std::uint32_t k) {
        return Vec2(in_box(particles[k].position.x()), in_box(particles[k].position.y()));
    };
    // About four disks a cell, and finer where they crowd (a cluster in an
    // empty box), so that a search looks at a few dozen disks, not thousands.
    const auto count = static_cast<std::uint32_t>(n);
    const int spread_side = UniformGrid::cells_per_side(side, 0.0, std::sqrt(static_cast<double>(n) / 4.0));
    const int finest =
        std::max(spread_side, static_cast<int>(std::min(psi6_most_cells_a_side,
                                                        std::sqrt(psi6_most_cells_per_disk * static_cast<double>(n)))));
    const UniformGrid grid(side,
                           refined_for_crowding(side, count, binned_at, spread_side, finest, psi6_most_cell_mates));
    const int per_side = grid.per_side();
    // Nothing outside the searched cells is closer than this many cells;
    // a hair less, for the rounding of a position's cell.
    const double reach_per_ring = grid.cell_size() * (1.0 - 1e-9);
    const PointsByCell by_cell(grid, count, binned_at);

    struct Neighbour {  // the bond itself is made again for the six nearest only
        double distance_sq;
        std::uint32_t index;
        bool operator<(const Neighbour& other) const {  // ties by index: the same six for any grid
            return distance_sq < other.distance_sq || (distance_sq == other.distance_sq && index < other.index);
        }
    };
    std::vector<Neighbour> found;
    // In a periodic box the rings wrap around the edges and every bond is the
    // nearest image's.
    const auto nearest = [&](double d) { return periodic ? nearest_image(d, side) : d; };
    const auto bond_to = [&](const Vec2& at, std::uint32_t j) {
        const Vec2 d = particles[j].position - at;
        return Vec2(nearest(d.x()), nearest(d.y()));
    };
    for (std::uint32_t i = 0; i < n; ++i) {
        const Vec2 at = particles[i].position;
        const int cx = grid.column_of(in_box(at.x())), cy = grid.column_of(in_box(at.y()));
        const auto visit_cell = [&](int x, int y) {
            by_cell.for_each_in(x, y, [&](std::uint32_t j) {
                if (j == i) return;
                found.push_back({bond_to(at, j).squaredNorm(), j});
            });
        };
        // The square of rings 0 to `ring` around the disk's cell is searched
        // ring by ring, each cell once, until the sixth nearest lies inside it.
        found.clear();
        for (int ring = 0;; ++ring) {
            const bool whole_box =
                periodic ? 2 * ring + 1 >= per_side
                         : cx - ring <= 0 && cy - ring <= 0 && cx + ring >= per_side - 1 && cy + ring >= per_side - 1;
            if (periodic && whole_box) {  // the rings would meet across the edges: every cell once
                found.clear();
                for (int y = 0; y < per_side; ++y) {
                    for (int x = 0; x < per_side; ++x) visit_cell(x, y);
                }
            } else {
                const auto place = [&](int c) { return periodic ? (c + per_side) % per_side : c; };
                for (int dy = -ring; dy <= ring; ++dy) {
                    const int y = cy + dy;
                    if (!periodic && (y < 0 || y >= per_side)) continue;
                    const int step = dy == -ring || dy == ring ? 1 : std::max(2 * ring, 1);
                    for (int dx = -ring; dx <= ring; dx += step) {
                        const int x = cx + dx;
                        if (!periodic && (x < 0 || x >= per_side)) continue;
                        visit_cell(place(x), place(y));
                    }
                }
            }
            if ((found.size() < 6 || ring == 0) && !whole_box) continue;  // ring 0 bounds nothing
            std::partial_sort(found.begin(), found.begin() + 6, found.end());
            const double reach = ring * reach_per_ring;
            if (whole_box || found[5].distance_sq < reach * reach) break;
        }
        std::complex<double> psi(0.0, 0.0);
        for (int k = 0; k < 6; ++k) {
            const Vec2 bond = bond_to(at, found[static_cast<std::size_t>(k)].index);
            const double length = std::sqrt(found[static_cast<std::size_t>(k)].distance_sq);
            if (!(length > 0.0)) continue;
            const std::complex<double> u(bond.x() / length, bond.y() / length);
            const std::complex<double> u2 = u * u;
            psi += u2 * u2 * u2;  // exp(6 i theta), without trigonometry
        }
        local[i] = psi / 6.0;
    }
    return local;
}

double mean_hexatic_order(std::span<const std::complex<double>> local) {
    if (local.size() < 7) return 0.0;
    std::complex<double> total(0.0, 0.0);
    for (const std::complex<double>& psi : local) total += psi;
    return std::abs(total / static_cast<double>(local.size()));
}

double hexatic_order(std::span<const Particle> particles, const World& world, Boundary boundary) {
    return mean_hexatic_order(local_hexatic_order(particles, world, boundary));
}

MeanWithError block_average(std::span<const double> samples, std::size_t blocks) {
    MeanWithError result;
    if (samples.empty()) return result;
    // Summed in units of the largest sample's power of two, which is exact,
    // so that samples near the largest double sum and square without
    // overflowing, and the same bits as unscaled sums everywhere else.
    double largest = 0.0;
    for (const double s : samples) largest = std::max(largest, std::fabs(s));
    int exponent = 0;
    if (std::isfinite(largest) && largest > 0.0) std::frexp(largest, &exponent);
    const auto scaled = [&](double s) { return std::ldexp(s, -exponent); };
    if (blocks < 2 || samples.size() < 2 * blocks) {
        double sum = 0.0;
        for (const double s : samples) sum += scaled(s);
        result.mean = std::ldexp(sum / static_cast<double>(samples.size()), exponent);
        return result;
    }
    const std::size_t per_block = samples.size() / blocks;
    std::vector<double> means(blocks, 0.0);
    for (std::size_t b = 0; b < blocks; ++b) {
        for (std::size_t k = 0; k < per_block; ++k) means[b] += scaled(samples[b * per_block + k]);
        means[b] /= static_cast<double>(per_block);
    }
    double mean = 0.0;
    for (const double m : means) mean += m;
    mean /= static_cast<double>(blocks);
    double spread = 0.0;
    for (const double m : means) spread += (m - mean) * (m - mean);
    result.mean = std::ldexp(mean, exponent);
    result.error =
        std::ldexp(std::sqrt(spread / static_cast<double>(blocks - 1) / static_cast<double>(blocks)), exponent);
    result.blocks = blocks;
    return result;
}

}  // namespace particlesim
