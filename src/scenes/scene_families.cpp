#include "particlesim/scene_families.hpp"

#include "core/box.hpp"
#include "core/physics.hpp"
#include "core/random.hpp"
#include "core/uniform_grid.hpp"
#include "input/scene_checks.hpp"
#include "io/number_format.hpp"
#include "scenes/growth_packing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace particlesim {

namespace {

Particle disk(double x, double y, double vx = 0.0, double vy = 0.0) {
    Particle p;
    p.position = Vec2(x, y);
    p.velocity = Vec2(vx, vy);
    return p;
}

// The family's scene, checked as its box holds it (a periodic family's centres lie in [0, L)).
Scene scene_of(const SceneFamilyOptions& options, double box_size, std::vector<Particle> particles,
               CentresIn centres = CentresIn::walled_box) {
    Scene scene;
    scene.world = World{box_size, options.radius};
    scene.steps = options.steps;
    scene.mode = options.mode;
    scene.particle_count = particles.size();
    scene.particles = std::move(particles);
    require_valid_scene("particlesim::make_family_scene", scene.world, scene.particles, centres);
    return scene;
}

SpeedRange speeds_or(const SceneFamilyOptions& options, SpeedRange fallback) {
    return options.speeds.value_or(fallback);
}

double area_fraction_or(const SceneFamilyOptions& options, double fallback, double most) {
    const double fraction = options.area_fraction.value_or(fallback);
    if (!(fraction > 0.0 && fraction <= most)) {
        throw std::invalid_argument("particlesim::make_family_scene: the area fraction must be in (0, " +
                                    format_short(most) + "], not " + format_short(fraction));
    }
    return fraction;
}

// The side of a box that holds `count` disks at `fraction` of its area.
double side_for(std::size_t count, double radius, double fraction) {
    return std::sqrt(static_cast<double>(std::max<std::size_t>(count, 1)) * std::numbers::pi * radius * radius /
                     fraction);
}

void give_random_velocities(std::vector<Particle>& particles, SpeedRange speeds, SplitMix64& rng) {
    for (Particle& p : particles) {
        const double speed = speeds.min + rng.uniform() * (speeds.max - speeds.min);
        p.velocity = speed * random_direction(rng);
    }
}

Scene random_scene(const SceneFamilyOptions& o) {
    const World world{o.box_size.value_or(20000.0), o.radius};
    RandomSceneOptions random{o.seed, o.speeds};
    return scene_of(o, world.box_size, make_random_particles(o.particles.value_or(1000), world, random));
}

Scene gas(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(400);
    const double box = side_for(count, o.radius, area_fraction_or(o, 0.3, 0.5));
    const RandomSceneOptions random{o.seed, speeds_or(o, {0.1 * o.radius, o.radius})};
    return scene_of(o, box, make_random_particles(count, World{box, o.radius}, random));
}

// Rows of disks 2r (1 + gap) apart, every other row shifted by half a
// spacing, each disk moved at random by at most 0.3 gap r on each axis (too
// little to make two overlap).
Scene lattice(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(400);
    const double r = o.radius;
    constexpr double gap = 0.05;
    const double spacing = 2.0 * r * (1.0 + gap);
    const double row_height = spacing * std::sqrt(3.0) / 2.0;
    const double jitter = 0.3 * gap * r;
    const auto columns = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count) * 2.0 / std::sqrt(3.0)))));
    const std::size_t rows = (count + columns - 1) / columns;
    const double margin = r + jitter;
    const double box = 2.0 * margin + std::max(spacing * (static_cast<double>(columns) - 0.5),
                                               row_height * static_cast<double>(rows > 0 ? rows - 1 : 0));
    SplitMix64 rng(o.seed);
    std::vector<Particle> particles;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t row = k / columns, column = k % columns;
        const double x = margin + spacing * (static_cast<double>(column) + (row % 2 == 1 ? 0.5 : 0.0));
        const double y = margin + row_height * static_cast<double>(row);
        const double dx = (2.0 * rng.uniform() - 1.0) * jitter;
        const double dy = (2.0 * rng.uniform() - 1.0) * jitter;
        particles.push_back(disk(std::clamp(x + dx, r, box - r), std::clamp(y + dy, r, box - r)));
    }
    give_random_velocities(particles, speeds_or(o, {0.01 * r, 0.1 * r}), rng);
    return scene_of(o, box, std::move(particles));
}

// Disks 4r apart on one line, all with the same velocity towards the left
// wall: the first bounces back into the second, and so on down the row.
Scene line(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(100);
    const double r = o.radius;
    const double box = o.box_size.value_or(4.0 * r * static_cast<double>(count + 1));
    const double row = 4.0 * r * static_cast<double>(count);  // the last disk's right edge
    if (box < row) {
        throw std::invalid_argument("particlesim::make_family_scene: " + std::to_string(count) +
                                    " disks 4r apart in a row need L >= 4 r N = " + format_brief(row) + ", not " +
                                    format_brief(box));
    }
    const double speed = speeds_or(o, {r, r}).max;
    std::vector<Particle> particles;
    for (std::size_t k = 0; k < count; ++k) {
        particles.push_back(disk(3.0 * r + 4.0 * r * static_cast<double>(k), box / 2.0, -speed, 0.0));
    }
    return scene_of(o, box, std::move(particles));
}

// N - 1 disks touching in a row at rest; disk 0 comes in from the left at
// r/2 per step and reaches the row after 8 steps. Under the step rules the
// momentum passes one disk per step (one collision per particle per step).
Scene cradle(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(5);
    if (count < 2) {
        throw std::invalid_argument(
            "particlesim::make_family_scene: Newton's cradle needs at least 2 disks (one "
            "moving into a row at rest), not " +
            std::to_string(count));
    }
    const double r = o.radius;
    const double box = 4.0 * r * static_cast<double>(count + 4);
    const double speed = speeds_or(o, {0.5 * r, 0.5 * r}).max;
    std::vector<Particle> particles{disk(box / 2.0 - 6.0 * r, box / 2.0, speed, 0.0)};
    for (std::size_t k = 1; k < count; ++k) {
        particles.push_back(disk(box / 2.0 + 2.0 * r * static_cast<double>(k - 1), box / 2.0));
    }
    return scene_of(o, box, std::move(particles));
}

// Four square clusters of random disks at the given area fraction, in the
// quarters of a box four clusters wide, drifting towards the centre.
Scene clusters(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(400);
    const double r = o.radius;
    const double fraction = area_fraction_or(o, 0.4, 0.5);
    const std::size_t per_cluster = (count + 3) / 4;
    const SpeedRange thermal = speeds_or(o, {0.0, 0.1 * r});
    // A cluster of a few disks is mostly its walls' margin, where no centre
    // may lie: random placement may not fill it at the fraction asked for
    // (4 clusters of 2 at 0.4 do not). Such clusters are drawn 5 % wider at
    // a time, each from its own seed, so that the clusters that fill keep
    // their scene.
    double side = side_for(per_cluster, r, fraction);
    for (int widening = 0;; ++widening) {
        try {
            const double box = 4.0 * side;
            std::vector<Particle> particles;
            for (int c = 0; c < 4 && particles.size() < count; ++c) {
                const std::size_t here = std::min(per_cluster, count - particles.size());
                const RandomSceneOptions random{o.seed + 1 + static_cast<std::uint64_t>(c), thermal};
                const Vec2 centre(box * (c % 2 == 0 ? 0.25 : 0.75), box * (c / 2 == 0 ? 0.25 : 0.75));
                const Vec2 drift = (Vec2(box / 2.0, box / 2.0) - centre).normalized() * (side / 20.0);
                for (Particle p : make_random_particles(here, World{side, r}, random)) {
                    p.position += centre - Vec2(side / 2.0, side / 2.0);
                    p.velocity += drift;
                    particles.push_back(p);
                }
            }
            return scene_of(o, box, std::move(particles));
        } catch (const SceneTooFull&) {
            // Larger clusters fill, or fail at a fraction random placement
            // cannot reach anywhere: say so as it did.
            if (per_cluster > 64 || widening == 20) throw;
        }
        side *= 1.05;
    }
}

// Motifs in units of r (exact for r a power of two) in a box of 64 r; each
// decides a tie rule in the first step with numbers every formula computes
// exactly (docs/checking.md lists them).
Scene ties(const SceneFamilyOptions& o) {
    const double r = o.radius;
    const double side = 64.0;
    std::vector<Particle> u;
    // A wall and a particle at t = 0.5 for particle 0: the wall wins.
    u.push_back(disk(2, 8, -2, 0));
    u.push_back(disk(1, 11, 0, -2));
    // The same at the right wall, mirrored, the disk at the wall listed
    // second: the wall (kind 0) still comes before the pair (2, 3).
    u.push_back(disk(side - 1, 11, 0, -2));
    u.push_back(disk(side - 2, 8, 2, 0));
    // Two pairs at t = 0.5 sharing the disk at rest (index 4): the lowest indices win.
    u.push_back(disk(32, 32));
    u.push_back(disk(29, 32, 2, 0));
    u.push_back(disk(35, 32, -2, 0));
    // The same with the shared disk last (index 9): (7, 9) before (8, 9).
    u.push_back(disk(29, 44, 2, 0));
    u.push_back(disk(35, 44, -2, 0));
    u.push_back(disk(32, 44));
    // Exact corners at t = 0.5: both velocity components flip.
    u.push_back(disk(2, 2, -2, -2));
    u.push_back(disk(side - 2, side - 2, 2, 2));
    // Two disjoint pairs meeting at exactly t = 1 (a candidate: t <= 1).
    u.push_back(disk(10, 20, 1, 0));
    u.push_back(disk(14, 20, -1, 0));
    u.push_back(disk(10, 26, 1, 0));
    u.push_back(disk(14, 26, -1, 0));
    // A wall reached at exactly t = 1.
    u.push_back(disk(3, 40, -2, 0));
    // A pair at t = 0.5 after which disk 18 reaches the wall exactly at the
    // end of the step: it stops there and bounces at t = 0 of the next step.
    u.push_back(disk(5, 52, -2, 0));
    u.push_back(disk(2, 52));
    for (Particle& p : u) {
        p.position *= r;
        p.velocity *= r;
    }
    return scene_of(o, side * r, std::move(u));
}

Scene fast(const SceneFamilyOptions& o) {
    // 100 r by default, wider where the disks would pass an area fraction of
    // 0.5 (from 1592 disks), which random placement cannot reach.
    const std::size_t count = o.particles.value_or(50);
    const double roomy = o.radius * std::sqrt(static_cast<double>(count) * std::numbers::pi / 0.5);
    const World world{o.box_size.value_or(std::max(100.0 * o.radius, roomy)), o.radius};
    const RandomSceneOptions random{o.seed, speeds_or(o, {2.0 * world.box_size, 5.0 * world.box_size})};
    return scene_of(o, world.box_size, make_random_particles(count, world, random));
}

// Half the disks sit on the four walls in turn (some moving into them: a
// wall collision at t = 0), the rest in pairs that touch, in rows inside.
Scene walls(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(64);
    const double r = o.radius;
    const std::size_t on_walls = count / 2;
    // Room for the pairs inside, and for the wall disks 4 r apart, a quarter
    // of them along each wall, 3 r from the corners and r to spare against
    // rounding (from 314 disks the walls need the more).
    const double along_walls = on_walls == 0 ? 0.0 : 7.0 * r + 4.0 * r * static_cast<double>((on_walls - 1) / 4);
    const double fitting_box =
        std::max(8.0 * r * std::ceil(std::sqrt(static_cast<double>(count))) + 16.0 * r, along_walls);
    const double box = o.box_size.value_or(fitting_box);
    const auto too_small = [&] {
        return std::invalid_argument("particlesim::make_family_scene: a box of side " + format_short(box) +
                                     " is too small for " + std::to_string(count) +
                                     " disks of the walls family (the default box for them, " +
                                     format_short(fitting_box) + ", fits)");
    };
    SplitMix64 rng(o.seed);
    std::vector<Particle> particles;
    for (std::size_t k = 0; k < on_walls; ++k) {
        const double along = 3.0 * r + 4.0 * r * static_cast<double>(k / 4);
        if (along > box - 3.0 * r) throw too_small();
        switch (k % 4) {
        case 0: particles.push_back(disk(r, along)); break;
        case 1: particles.push_back(disk(along, r)); break;
        case 2: particles.push_back(disk(box - r, box - along)); break;
        default: particles.push_back(disk(box - along, box - r)); break;
        }
    }
    for (double y = 5.0 * r; particles.size() < count; y += 4.0 * r) {
        if (y > box - 5.0 * r) throw too_small();
        for (double x = 5.0 * r; x + 2.0 * r <= box - 5.0 * r && particles.size() < count; x += 6.0 * r) {
            particles.push_back(disk(x, y));
            if (particles.size() < count) particles.push_back(disk(x + 2.0 * r, y));
        }
    }
    give_random_velocities(particles, speeds_or(o, {0.1 * r, r}), rng);
    return scene_of(o, box, std::move(particles));
}

// The rows and columns of a triangular lattice for `count` disks, and how
// wide and tall it is in units of its spacing (every other row shifted by
// half a spacing; the last row may be short).
struct LatticeShape {
    std::size_t columns = 1;
    std::size_t rows = 1;
    double width = 0.0;   // spacings
    double height = 0.0;  // spacings
    [[nodiscard]] double extent() const { return std::max(width, height); }
};

LatticeShape lattice_shape(std::size_t count, std::size_t columns) {
    LatticeShape shape;
    shape.columns = columns;
    shape.rows = (count + columns - 1) / columns;
    shape.width = static_cast<double>(columns) - (shape.rows > 1 ? 0.5 : 1.0);
    shape.height = static_cast<double>(shape.rows - 1) * std::sqrt(3.0) / 2.0;
    return shape;
}

// The shape whose larger side is the fewest spacings: the widest spacing in a square.
LatticeShape squarest_lattice(std::size_t count) {
    LatticeShape best = lattice_shape(count, 1);
    for (std::size_t columns = 2; columns <= count; ++columns) {
        const LatticeShape shape = lattice_shape(count, columns);
        if (shape.extent() < best.extent()) best = shape;
    }
    return best;
}

// A standard normal deviate (Marsaglia's polar method).
double standard_normal(SplitMix64& rng) {
    for (;;) {
        const double u = 2.0 * rng.uniform() - 1.0;
        const double v = 2.0 * rng.uniform() - 1.0;
        const double s = u * u + v * v;
        if (s > 0.0 && s < 1.0) return u * std::sqrt(-2.0 * std::log(s) / s);
    }
}

// Neighbours on the lattice are kept this much farther apart than 2r, so
// that rounding the positions never makes two touch.
constexpr double crystal_clearance = 1e-9;

// Maxwell velocities at kT (mass 1) shifted to zero total momentum and
// scaled so that the kinetic energy is exactly (N - 1) kT: the 2 (N - 1)
// degrees of freedom that the fixed momentum leaves.
void give_maxwell_velocities(std::vector<Particle>& particles, double kT, std::uint64_t seed) {
    const std::size_t count = particles.size();
    SplitMix64 rng(seed);
    Vec2 momentum(0.0, 0.0);
    for (Particle& p : particles) {
        p.velocity = Vec2(standard_normal(rng), standard_normal(rng));
        momentum += p.velocity;
    }
    double kinetic = 0.0;
    for (Particle& p : particles) {
        p.velocity -= momentum / static_cast<double>(count);
        kinetic += 0.5 * p.velocity.squaredNorm();
    }
    const double scale = kinetic > 0.0 ? std::sqrt(static_cast<double>(count - 1) * kT / kinetic) : 0.0;
    for (Particle& p : particles) p.velocity *= scale;
}

// The Maxwell velocities' spread is sqrt(kT) a component; the largest of
// ten million draws is under 6 spreads, so up to 1e116 every component stays
// inside the accepted range (1e60).
constexpr double highest_temperature = 1e116;

double checked_temperature(const SceneFamilyOptions& o) {
    const double kT = o.temperature.value_or(0.25 * o.radius * o.radius);
    if (!(kT >= 0.0 && kT <= highest_temperature)) {
        throw std::invalid_argument(
            "particlesim::make_family_scene: the temperature must be in [0, 1e116] (speeds "
            "within the accepted range), not " +
            format_short(kT));
    }
    return kT;
}

// A lattice that fills a periodic box: `rows` rows (an even number, so that
// shifting every other row by half a spacing still wraps) of `columns`
// disks; with columns / rows near 2 / sqrt(3) it is nearly triangular. Where
// N has no such factors (N odd), square rows of equal length. Closest
// neighbours: along a row, L / columns; between rows, the diagonal; and two
// rows up in the same column.
Scene periodic_crystal(const SceneFamilyOptions& o, std::size_t count) {
    const double r = o.radius;
    const double kT = checked_temperature(o);
    // The factorisation whose spacing between neighbours is widest for its box.
    std::size_t columns = count, rows = 1;
    bool shifted = false;
    double best = 0.0;                                          // the closest neighbours' distance, in units of L
    const std::size_t sized = std::max<std::size_t>(count, 1);  // no disks: the box of one
    for (std::size_t c = 1; c <= sized; ++c) {
        if (sized % c != 0) continue;
        const std::size_t n_rows = sized / c;
        const bool shift = n_rows % 2 == 0;
        const double along = 1.0 / static_cast<double>(c), between = 1.0 / static_cast<double>(n_rows);
        const double across = shift ? std::hypot(0.5 * along, between) : between;
        // Two rows up, the same column: 2 rows' height (shifted rows), or one row (unshifted).
        const double closest = std::min({along, across, shift ? 2.0 * between : between});
        if (closest > best) {
            best = closest;
            columns = c;
            rows = n_rows;
            shifted = shift;
        }
    }
    const double densest_box = 2.0 * r * (1.0 + crystal_clearance) / best;
    const double densest = std::min(static_cast<double>(sized) * std::numbers::pi * r * r / (densest_box * densest_box),
                                    close_packing_fraction);
    const double fraction =
        o.area_fraction ? area_fraction_or(o, 0.7, close_packing_fraction) : std::min(0.7, 0.95 * densest);
    const double box = side_for(count, r, fraction);
    if (count > 1 && !(best * box >= 2.0 * r * (1.0 + crystal_clearance))) {
        throw std::invalid_argument("particlesim::make_family_scene: " + std::to_string(count) +
                                    " disks do not fit a lattice in a periodic box at area fraction " +
                                    format_short(fraction) + "; the densest that fits is " + format_short(densest));
    }
    // The exact engine's periodic box holds 5 cells of a contact distance (its own test).
    const World world{box, r};
    if (!holds_contact_cells(world, periodic_cells_at_least)) {
        const double reach = contact_reach(Box::of(world));
        throw std::invalid_argument("particlesim::make_family_scene: a periodic box must be wider than " +
                                    std::to_string(periodic_cells_at_least) + " contact distances (" +
                                    format_short(periodic_cells_at_least * reach) + "), not " + format_short(box) +
                                    ": more disks or a lower fraction");
    }
    const double along = box / static_cast<double>(columns), between = box / static_cast<double>(rows);
    std::vector<Particle> particles;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t row = k / columns, column = k % columns;
        const double x = along * (static_cast<double>(column) + (shifted && row % 2 == 1 ? 0.5 : 0.0) + 0.25);
        const double y = between * (static_cast<double>(row) + 0.5);
        particles.push_back(disk(x, y));
    }
    give_maxwell_velocities(particles, kT, o.seed);
    return scene_of(o, box, std::move(particles), CentresIn::periodic_box);
}

// A triangular lattice centred in the walled box at the area fraction asked
// for (N pi r^2 / L^2), up to the densest at which it fits (neighbours 2r
// apart, and r from the walls); Maxwell velocities at kT with zero total
// momentum, scaled so that the kinetic energy is exactly (N - 1) kT: the
// 2 (N - 1) degrees of freedom that the fixed momentum leaves.
Scene crystal(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(400);
    if (o.boundary == Boundary::periodic) return periodic_crystal(o, count);
    const double r = o.radius;
    const LatticeShape shape = squarest_lattice(std::max<std::size_t>(count, 1));
    const double densest_box = 2.0 * r + 2.0 * r * (1.0 + crystal_clearance) * shape.extent();
    // (No disks: the box of one.)
    const double densest = std::min(
        static_cast<double>(std::max<std::size_t>(count, 1)) * std::numbers::pi * r * r / (densest_box * densest_box),
        close_packing_fraction);
    // Unasked: 0.7, or a little below the densest for the few disks that cannot reach it.
    const double fraction =
        o.area_fraction ? area_fraction_or(o, 0.7, close_packing_fraction) : std::min(0.7, 0.95 * densest);
    const double kT = checked_temperature(o);
    const double box = side_for(count, r, fraction);
    const double room = box - 2.0 * r;  // for the centres
    const double spacing = shape.extent() > 0.0 ? room / shape.extent() : room;
    if (count > 1 && !(spacing >= 2.0 * r * (1.0 + crystal_clearance))) {
        throw std::invalid_argument("particlesim::make_family_scene: " + std::to_string(count) +
                                    " disks do not fit a triangular lattice in a walled box at area fraction " +
                                    format_short(fraction) + "; the densest that fits is " + format_short(densest));
    }
    const double row_height = spacing * std::sqrt(3.0) / 2.0;
    const double left = (box - spacing * shape.width) / 2.0;
    const double bottom = (box - row_height * static_cast<double>(shape.rows - 1)) / 2.0;
    std::vector<Particle> particles;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t row = k / shape.columns, column = k % shape.columns;
        const double x = left + spacing * (static_cast<double>(column) + (row % 2 == 1 ? 0.5 : 0.0));
        const double y = bottom + row_height * static_cast<double>(row);
        particles.push_back(disk(std::clamp(x, r, box - r), std::clamp(y, r, box - r)));
    }
    give_maxwell_velocities(particles, kT, o.seed);
    return scene_of(o, box, std::move(particles));
}

// A random packing grown by Lubachevsky-Stillinger compression to the area
// fraction asked for (default 0.7), scaled to the radius asked for; then
// Maxwell velocities at kT as the crystal's. Fast growth jams below close
// packing; slow growth stays near equilibrium (and orders at high density).
Scene compressed(const SceneFamilyOptions& o) {
    const std::size_t count = o.particles.value_or(400);
    const double fraction = o.area_fraction.value_or(0.7);
    const double kT = checked_temperature(o);
    const bool periodic = o.boundary == Boundary::periodic;
    const GrownPacking grown = grow_packing(
        {count, fraction, o.growth_rate.value_or(default_growth_rate), periodic, o.seed, o.compression_progress});
    const double box = side_for(count, o.radius, fraction);
    const double scale = box / std::max(grown.box_size, 1.0);
    std::vector<Particle> particles;
    for (const Vec2& centre : grown.centres) {
        Vec2 at = centre * scale;
        for (int axis = 0; axis < 2; ++axis) {
            at[axis] =
                periodic ? wrap_into_periodic_box(at[axis], box) : std::clamp(at[axis], o.radius, box - o.radius);
        }
        particles.push_back(disk(at.x(), at.y()));
    }
    give_maxwell_velocities(particles, kT, o.seed);
    return scene_of(o, box, std::move(particles), periodic ? CentresIn::periodic_box : CentresIn::walled_box);
}

// The settings of SceneFamilyOptions that a family takes, beyond the radius,
// steps, mode and seed that every family accepts. One it has no use for is
// refused rather than ignored: `gas` with a box size would otherwise give a
// box of another side without a word.
struct SettingsTaken {
    bool particles = true;
    bool box_size = false;
    bool area_fraction = false;
    bool speeds = true;
    bool temperature = false;
    bool periodic = false;
    bool growth_rate = false;
};

SettingsTaken settings_taken(SceneFamily family) {
    switch (family) {
    case SceneFamily::random:
    case SceneFamily::line:
    case SceneFamily::fast:
    case SceneFamily::walls: return {.box_size = true};
    case SceneFamily::gas:
    case SceneFamily::clusters: return {.area_fraction = true};
    case SceneFamily::lattice:
    case SceneFamily::cradle: return {};
    case SceneFamily::ties: return {.particles = false, .speeds = false};
    case SceneFamily::crystal: return {.area_fraction = true, .speeds = false, .temperature = true, .periodic = true};
    case SceneFamily::compressed:
        return {.area_fraction = true, .speeds = false, .temperature = true, .periodic = true, .growth_rate = true};
    }
    return {};
}

void refuse_settings_not_taken(SceneFamily family, const SceneFamilyOptions& o) {
    struct Setting {
        bool given;
        bool taken;
        const char* words;
    };
    const SettingsTaken taken = settings_taken(family);
    const Setting settings[] = {
        {o.particles.has_value(), taken.particles, "a particle count"},
        {o.box_size.has_value(), taken.box_size, "a box size"},
        {o.area_fraction.has_value(), taken.area_fraction, "an area fraction"},
        {o.speeds.has_value(), taken.speeds, "speeds"},
        {o.temperature.has_value(), taken.temperature, "a temperature"},
        {o.boundary == Boundary::periodic, taken.periodic, "a periodic box"},
        {o.growth_rate.has_value(), taken.growth_rate, "a growth rate"},
    };
    for (const Setting& refused : settings) {
        if (!refused.given || refused.taken) continue;
        std::vector<const char*> takes;
        for (const Setting& setting : settings) {
            if (setting.taken) takes.push_back(setting.words);
        }
        std::string list;  // "a, b and c"
        for (std::size_t j = 0; j < takes.size(); ++j) {
            list += (j == 0 ? "" : j + 1 == takes.size() ? " and " : ", ") + std::string(takes[j]);
        }
        throw std::invalid_argument(
            "particlesim::make_family_scene: this family has no use for " + std::string(refused.words) +
            (takes.empty() ? std::string("; its particles and box are its own") : "; it takes " + list));
    }
}

}  // namespace

const std::vector<SceneFamilyInfo>& scene_families() {
    static const std::vector<SceneFamilyInfo> families{
        {SceneFamily::random, "random", "the rules' random scene, exactly as simcli draws it for N, L, r and --seed"},
        {SceneFamily::gas, "gas", "random disks at an area fraction (default 0.3), speeds 0.1 r to r per step"},
        {SceneFamily::lattice, "lattice",
         "a perturbed triangular lattice, area fraction about 0.8: denser than random placement"},
        {SceneFamily::line, "line", "N disks in one row moving together into a wall: the original design's worst case"},
        {SceneFamily::cradle, "cradle", "Newton's cradle: a touching row at rest, one disk moving into it"},
        {SceneFamily::clusters, "clusters", "four dense clusters in an empty box, drifting into each other"},
        {SceneFamily::ties, "ties",
         "simultaneous collisions in exact numbers: walls before pairs, lowest indices, corners, t = 1"},
        {SceneFamily::fast, "fast", "speeds of 2 to 5 box sides per step"},
        {SceneFamily::walls, "walls", "disks starting on the walls and pairs starting in contact"},
        {SceneFamily::crystal, "crystal",
         "a triangular lattice at any area fraction up to close packing (default 0.7), Maxwell velocities, no "
         "total momentum"},
        {SceneFamily::compressed, "compressed",
         "a random packing grown to an area fraction (default 0.7) by Lubachevsky-Stillinger compression, "
         "Maxwell velocities, no total momentum"},
    };
    return families;
}

std::optional<SceneFamily> scene_family_named(std::string_view name) {
    for (const SceneFamilyInfo& info : scene_families()) {
        if (name == info.name) return info.family;
    }
    return std::nullopt;
}

Scene make_family_scene(SceneFamily family, const SceneFamilyOptions& options) {
    if (options.steps < 0) throw std::invalid_argument("particlesim::make_family_scene: steps must be >= 0");
    // Checked first: several families derive the box from the radius, whose own check would name the box.
    if (!(options.radius >= min_length && options.radius <= max_magnitude)) {
        throw std::invalid_argument(
            "particlesim::make_family_scene: the radius must lie in [1e-60, 1e60] (the "
            "accepted range), not " +
            format_brief(options.radius));
    }
    if (options.particles && *options.particles > max_particle_count()) {
        throw std::invalid_argument("particlesim::make_family_scene: " + std::to_string(*options.particles) +
                                    " particles are more than this machine can hold (at most " +
                                    std::to_string(max_particle_count()) + ")");
    }
    refuse_settings_not_taken(family, options);
    switch (family) {
    case SceneFamily::random: return random_scene(options);
    case SceneFamily::gas: return gas(options);
    case SceneFamily::lattice: return lattice(options);
    case SceneFamily::line: return line(options);
    case SceneFamily::cradle: return cradle(options);
    case SceneFamily::clusters: return clusters(options);
    case SceneFamily::ties: return ties(options);
    case SceneFamily::fast: return fast(options);
    case SceneFamily::walls: return walls(options);
    case SceneFamily::crystal: return crystal(options);
    case SceneFamily::compressed: return compressed(options);
    }
    throw std::invalid_argument("particlesim::make_family_scene: unknown family");
}

void write_scene(std::ostream& out, const Scene& scene) {
    // Refused rather than written as text that the scene reader refuses.
    const auto refuse = [](const std::string& what) {
        throw std::invalid_argument("particlesim::write_scene: " + what);
    };
    const auto length_in_range = [](double length) { return length >= min_length && length <= max_magnitude; };
    if (!length_in_range(scene.world.box_size) || !length_in_range(scene.world.radius))
        refuse("the box size and the radius must lie in [1e-60, 1e60] (the accepted range)");
    if (scene.steps < 0) refuse("steps must be >= 0");
    if (scene.mode != OutputMode::print && scene.mode != OutputMode::perf) refuse("the mode must be print or perf");
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        const Particle& p = scene.particles[i];
        for (const double value : {p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y()}) {
            if (!(std::fabs(value) <= max_magnitude))
                refuse("particle " + std::to_string(i) + " has a number beyond the accepted range (or NaN)");
        }
    }
    // A random scene (N > 0, no particle listed) is its first lines: the
    // reader draws the same particles again.
    const std::size_t count = scene.particles.empty() ? scene.particle_count : scene.particles.size();
    char number[32];
    const auto shortest = [&](double value) { return std::string(number, write_shortest(number, value)); };
    out << count << '\n'
        << shortest(scene.world.box_size) << '\n'
        << shortest(scene.world.radius) << '\n'
        << scene.steps << '\n'
        << (scene.mode == OutputMode::print ? "print" : "perf") << '\n';
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        const Particle& p = scene.particles[i];
        out << i << ' ' << shortest(p.position.x()) << ' ' << shortest(p.position.y()) << ' '
            << shortest(p.velocity.x()) << ' ' << shortest(p.velocity.y()) << '\n';
    }
}

}  // namespace particlesim
