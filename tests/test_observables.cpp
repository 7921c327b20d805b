// Observables: the collision sums on hand-built collisions worked out on
// paper; the pressure's two routes (virial, walls) agreeing within their
// error bars in a walled box, and the ideal gas's P A = N kT; |psi6| near 1 on
// a lattice, near 0 in a gas, unchanged by a rotation and, in a periodic
// box, by unwrapped coordinates; refusals of what cannot be measured; block averages on
// series whose answer is known; and simcli's --observables file and --stats.

#include "check.hpp"
#include "disk.hpp"
#include "run_process.hpp"

#include "particlesim/accuracy.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/scene_families.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace particlesim;

namespace {

using test_scenes::disk;

void sums_of_hand_built_collisions() {
    // Head on along x, r = 1, speeds 1 each way: one collision at t = 1;
    // r_ab . dp_a = (-2, 0) . (-2, 0) = 4. No wall is reached in the step.
    ExactSimulation pair(World{20.0, 1.0}, {disk(7, 10, 1, 0), disk(11, 10, -1, 0)});
    pair.step();
    CHECK_EQ(pair.totals().particle_collisions, std::uint64_t{1});
    CHECK_NEAR(pair.collision_sums().pair_virial, 4.0, 1e-12);
    CHECK_EQ(pair.collision_sums().wall_impulse, 0.0);
    // One disk into the left wall at speed 3, another into a corner at (2, 1):
    // impulses 2 x 3, and 2 x (2 + 1) for the corner's two walls.
    ExactSimulation walls(World{20.0, 1.0}, {disk(2.5, 10, -3, 0), disk(3, 3, -2, -2)});
    walls.step();
    CHECK_EQ(walls.totals().wall_collisions, std::uint64_t{2});
    CHECK_NEAR(walls.collision_sums().wall_impulse, 6.0 + 8.0, 1e-12);
}

// Runs a scene, taking the pressure of every `every` steps.
struct Routes {
    MeanWithError virial, walls;
};

Routes pressure_routes(const Scene& scene, int steps, int every) {
    ExactSimulation engine(scene.world, scene.particles);
    std::vector<double> virial, walls;
    CollisionSums before = engine.collision_sums();
    for (int s = 1; s <= steps; ++s) {
        engine.step();
        if (s % every != 0) continue;
        double kinetic = 0.0;
        for (const Particle& p : engine.particles()) kinetic += 0.5 * p.velocity.squaredNorm();
        const Pressure p = walled_box_pressure(scene.world, scene.particles.size(), kinetic,
                                               engine.collision_sums() - before, static_cast<double>(every));
        virial.push_back(p.Z);
        walls.push_back(p.Z_walls);
        before = engine.collision_sums();
    }
    return {block_average(virial), block_average(walls)};
}

void the_two_routes_agree_in_a_walled_box() {
    SceneFamilyOptions o;
    o.particles = 400;
    o.area_fraction = 0.3;
    o.speeds = SpeedRange{0.5, 0.5};
    const Routes gas = pressure_routes(make_family_scene(SceneFamily::gas, o), 3200, 10);
    const double combined = std::hypot(gas.virial.error, gas.walls.error);
    check::Context context("Z virial ", gas.virial.mean, " +- ", gas.virial.error, ", walls ", gas.walls.mean, " +- ",
                           gas.walls.error);
    CHECK(gas.virial.error > 0.0 && gas.walls.error > 0.0);
    CHECK(std::abs(gas.virial.mean - gas.walls.mean) <= 4.0 * combined);
    // Hard disks at 0.3 press about twice as hard as an ideal gas.
    CHECK(gas.virial.mean > 1.8 && gas.virial.mean < 2.4);
    // Disks so small that they almost never meet: P A = N kT by the walls alone.
    o.radius = 1e-3;
    o.area_fraction = 1e-5;
    const Routes ideal = pressure_routes(make_family_scene(SceneFamily::gas, o), 3200, 10);
    check::Context ideal_context("ideal: Z walls ", ideal.walls.mean, " +- ", ideal.walls.error);
    CHECK(std::abs(ideal.walls.mean - 1.0) <= 4.0 * ideal.walls.error);
    CHECK(std::abs(ideal.virial.mean - 1.0) <= 1e-3);
}

void hexatic_order_of_lattice_and_gas() {
    SceneFamilyOptions o;
    o.particles = 900;
    o.area_fraction = 0.8;
    const Scene crystal = make_family_scene(SceneFamily::crystal, o);
    const double ordered = hexatic_order(crystal.particles, crystal.world);
    check::Context context("crystal |psi6| ", ordered);
    CHECK(ordered > 0.85 && ordered <= 1.0 + 1e-12);
    // Turned by 17 degrees about the box's centre (in a box large enough): the same magnitude.
    const double turn = 17.0 * std::numbers::pi / 180.0, c = std::cos(turn), s = std::sin(turn);
    std::vector<Particle> turned = crystal.particles;
    const World large{3.0 * crystal.world.box_size, crystal.world.radius};
    for (Particle& p : turned) {
        const Vec2 d = p.position - Vec2(crystal.world.box_size / 2, crystal.world.box_size / 2);
        p.position = Vec2(large.box_size / 2, large.box_size / 2) + Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
    }
    CHECK_NEAR(hexatic_order(turned, large), ordered, 1e-9);
    // Each disk's own psi6 turns by 6 x 17 degrees.
    const std::vector<std::complex<double>> before = local_hexatic_order(crystal.particles, crystal.world);
    const std::vector<std::complex<double>> after = local_hexatic_order(turned, large);
    const std::complex<double> rotation = std::polar(1.0, 6.0 * turn);
    double worst = 0.0;
    for (std::size_t i = 0; i < before.size(); ++i) worst = std::max(worst, std::abs(after[i] - before[i] * rotation));
    CHECK(worst < 1e-9);
    std::complex<double> mean(0.0, 0.0);
    for (const std::complex<double>& psi : before) mean += psi;
    CHECK_NEAR(std::abs(mean / static_cast<double>(before.size())), ordered, 1e-12);
    // A lattice filling a periodic box: every disk sees the same neighbours by
    // the nearest images, so shifting the whole lattice changes nothing; without
    // the images, the disks at the edges miss theirs.
    SceneFamilyOptions p;
    p.particles = 870;
    p.area_fraction = 0.7;
    p.boundary = Boundary::periodic;
    const Scene filled = make_family_scene(SceneFamily::crystal, p);
    const double periodic_order = hexatic_order(filled.particles, filled.world, Boundary::periodic);
    std::vector<Particle> shifted = filled.particles;
    for (Particle& q : shifted) {
        for (int axis = 0; axis < 2; ++axis) {
            q.position[axis] =
                std::fmod(q.position[axis] + filled.world.box_size * (axis == 0 ? 0.37 : 0.61), filled.world.box_size);
        }
    }
    CHECK_NEAR(hexatic_order(shifted, filled.world, Boundary::periodic), periodic_order, 1e-9);
    // Every disk of it sees the same neighbourhood: one psi6 for all.
    const std::vector<std::complex<double>> alike =
        local_hexatic_order(filled.particles, filled.world, Boundary::periodic);
    double farthest = 0.0;
    for (const std::complex<double>& psi : alike) farthest = std::max(farthest, std::abs(psi - alike[0]));
    CHECK(farthest < 1e-9);
    CHECK_NEAR(std::abs(alike[0]), periodic_order, 1e-9);
    CHECK(hexatic_order(filled.particles, filled.world) < periodic_order - 0.01);
    // The same disks given whole sides outside the box (unwrapped
    // coordinates, as a trajectory that follows each disk keeps them): the
    // same neighbours, the same psi6 each.
    std::vector<Particle> unwrapped = shifted;
    for (std::size_t k = 0; k < unwrapped.size(); ++k) {
        const double sides_x = static_cast<double>(static_cast<int>(k % 7) - 3);
        const double sides_y = static_cast<double>(static_cast<int>(k % 5) - 2);
        unwrapped[k].position += filled.world.box_size * Vec2(sides_x, sides_y);
    }
    const std::vector<std::complex<double>> wrapped_local =
        local_hexatic_order(shifted, filled.world, Boundary::periodic);
    const std::vector<std::complex<double>> unwrapped_local =
        local_hexatic_order(unwrapped, filled.world, Boundary::periodic);
    double unwrapped_worst = 0.0;
    for (std::size_t k = 0; k < wrapped_local.size(); ++k)
        unwrapped_worst = std::max(unwrapped_worst, std::abs(unwrapped_local[k] - wrapped_local[k]));
    check::Context unwrapped_context("worst difference of a disk's psi6 unwrapped ", unwrapped_worst);
    CHECK(unwrapped_worst < 1e-9);
    o.particles = 2000;
    o.area_fraction = 0.3;
    const Scene gas = make_family_scene(SceneFamily::gas, o);
    CHECK(hexatic_order(gas.particles, gas.world) < 0.1);
    CHECK_EQ(hexatic_order(std::vector<Particle>(gas.particles.begin(), gas.particles.begin() + 6), gas.world), 0.0);
}

// Each disk's psi6 against a search of every disk (the six nearest, ties to
// the lower index; bonds to the nearest image in a periodic box): the same
// bits, on every family, in a periodic box, on square lattices (where the
// sixth nearest ties with two more), and on a crowded cluster in a corner of
// a large box (where the search refines its cells).
std::vector<std::complex<double>> psi6_of_every_pair(const std::vector<Particle>& particles, double side,
                                                     bool periodic) {
    const auto nearest = [&](double d) { return periodic ? d - side * std::round(d / side) : d; };
    std::vector<std::complex<double>> local(particles.size());
    if (particles.size() < 7) return local;
    for (std::size_t i = 0; i < particles.size(); ++i) {
        std::vector<std::pair<std::pair<double, std::size_t>, Vec2>> bonds;
        for (std::size_t j = 0; j < particles.size(); ++j) {
            if (j == i) continue;
            const Vec2 d = particles[j].position - particles[i].position;
            const Vec2 bond(nearest(d.x()), nearest(d.y()));
            bonds.push_back({{bond.squaredNorm(), j}, bond});
        }
        std::sort(bonds.begin(), bonds.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::complex<double> psi(0.0, 0.0);
        for (int k = 0; k < 6; ++k) {
            const Vec2 bond = bonds[static_cast<std::size_t>(k)].second;
            const double length = std::sqrt(bonds[static_cast<std::size_t>(k)].first.first);
            if (!(length > 0.0)) continue;
            const std::complex<double> u(bond.x() / length, bond.y() / length);
            const std::complex<double> u2 = u * u;
            psi += u2 * u2 * u2;
        }
        local[i] = psi / 6.0;
    }
    return local;
}

void hexatic_order_against_every_pair() {
    struct Case {
        std::string name;
        std::vector<Particle> particles;
        World world;
        Boundary boundary;
    };
    std::vector<Case> cases;
    for (const SceneFamilyInfo& info : scene_families()) {
        SceneFamilyOptions o;
        if (info.family != SceneFamily::ties) o.particles = 300;
        try {
            const Scene scene = make_family_scene(info.family, o);
            cases.push_back({info.name, scene.particles, scene.world, Boundary::walls});
        } catch (const std::invalid_argument&) {
        }
    }
    for (const SceneFamily family : {SceneFamily::crystal, SceneFamily::compressed}) {
        SceneFamilyOptions o;
        o.particles = 400;
        o.boundary = Boundary::periodic;
        const Scene scene = make_family_scene(family, o);
        cases.push_back({"periodic", scene.particles, scene.world, Boundary::periodic});
    }
    // Square lattices, 9 x 9 and 12 x 12, spacing 3: four second neighbours tie.
    for (const int rows : {9, 12}) {
        std::vector<Particle> square;
        for (int k = 0; k < rows * rows; ++k)
            square.push_back(disk(1.5 + 3.0 * (k % rows), 1.5 + 3.0 * (k / rows), 0, 0));
        cases.push_back({"square lattice", square, World{3.0 * rows, 1.0}, Boundary::walls});
        cases.push_back({"square lattice", square, World{3.0 * rows, 1.0}, Boundary::periodic});
    }
    // 2500 touching disks in a corner of a box 20 000 wide, 30 strewn far away.
    std::vector<Particle> cluster;
    for (int k = 0; k < 2500; ++k) {
        const int row = k / 50, column = k % 50;
        cluster.push_back(disk(10.0 + 2.0 * column + (row % 2 == 0 ? 0.0 : 1.0), 10.0 + std::sqrt(3.0) * row, 0, 0));
    }
    for (int k = 0; k < 30; ++k) cluster.push_back(disk(5000.0 + 450.0 * k, 19000.0 - 97.0 * k, 0, 0));
    cases.push_back({"cluster", cluster, World{20000.0, 1.0}, Boundary::walls});
    cases.push_back({"cluster", cluster, World{20000.0, 1.0}, Boundary::periodic});
    for (std::size_t count = 1; count <= 12; ++count) {
        std::vector<Particle> few;
        for (std::size_t k = 0; k < count; ++k)
            few.push_back(
                disk(2.0 + 3.7 * static_cast<double>(k * 7 % 11), 2.0 + 5.3 * static_cast<double>(k * 3 % 7), 0, 0));
        cases.push_back({"few", few, World{60.0, 1.0}, Boundary::walls});
        cases.push_back({"few", few, World{60.0, 1.0}, Boundary::periodic});
    }
    CHECK(cases.size() >= 40);
    for (const Case& c : cases) {
        const check::Context context(c.name, ", ", c.particles.size(), " disks, ",
                                     c.boundary == Boundary::periodic ? "periodic" : "walls");
        const std::vector<std::complex<double>> searched = local_hexatic_order(c.particles, c.world, c.boundary);
        const std::vector<std::complex<double>> every =
            psi6_of_every_pair(c.particles, c.world.box_size, c.boundary == Boundary::periodic);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < every.size(); ++i) differ += searched[i] != every[i];
        CHECK_EQ(differ, 0U);
    }
}

// What cannot be measured is refused with the function's name, not
// answered: a position that is no number, a box of no size, a Boundary cast
// from a number that names no box, and a pressure's inputs that no run gives.
void what_cannot_be_measured_is_refused() {
    SceneFamilyOptions o;
    o.particles = 200;
    const Scene gas = make_family_scene(SceneFamily::gas, o);
    const auto refused = [](auto&& call, const std::string& words) {
        try {
            call();
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            check::Context context("message ", message);
            CHECK(message.find(words) != std::string::npos);
            return;
        }
        CHECK(!"refused");
    };
    std::vector<Particle> broken = gas.particles;
    broken[17].position.x() = std::nan("");
    refused([&] { return hexatic_order(broken, gas.world); }, "particle 17's position is not a finite number");
    broken[17].position.x() = INFINITY;
    refused([&] { return local_hexatic_order(broken, gas.world, Boundary::periodic); }, "particle 17");
    refused(
        [&] {
            return hexatic_order(gas.particles, World{0.0, 1.0}, Boundary::periodic);
        },
        "the box size must be finite and positive");
    refused([&] { return hexatic_order(gas.particles, gas.world, static_cast<Boundary>(9)); },
            "particlesim::local_hexatic_order: boundary must be Boundary::walls or Boundary::periodic, not 9");
    refused(
        [&] { return box_pressure(gas.world, static_cast<Boundary>(9), 200, 1.0, Vec2::Zero(), CollisionSums{}, 1.0); },
        "particlesim::box_pressure: boundary must be");
    // A pressure's inputs that no run gives: a world the engines refuse (their
    // check), a kinetic energy that is none, a momentum that is not these disks'.
    const CollisionSums some{3.0, 2.0};
    refused(
        [&] {
            return walled_box_pressure(World{1.0, 1.0}, 3, 5.0, some, 1.0);
        },
        "particlesim::walled_box_pressure: 2 * radius must be <= box size");
    refused(
        [&] {
            return walled_box_pressure(World{INFINITY, 1.0}, 3, 5.0, some, 1.0);
        },
        "particlesim::walled_box_pressure: box size must lie in [1e-60, 1e60] (the accepted range)");
    refused([&] { return walled_box_pressure(gas.world, 3, -5.0, some, 1.0); },
            "the kinetic energy must be finite and not negative, not -5");
    refused([&] { return box_pressure(gas.world, Boundary::periodic, 3, std::nan(""), Vec2::Zero(), some, 1.0); },
            "particlesim::periodic_box_pressure: the kinetic energy must be finite and not negative, not nan");
    refused([&] { return periodic_box_pressure(gas.world, 10, 1.0, Vec2(10.0, 0.0), some, 1.0); },
            "the total momentum's energy |P|^2 / 2N = 5 exceeds the kinetic energy 1: not the momentum of these 10 "
            "disks");
    refused([&] { return periodic_box_pressure(gas.world, 10, 1.0, Vec2(0.0, INFINITY), some, 1.0); },
            "the total momentum must be finite, not (0, inf)");
}

void block_averages_of_known_series() {
    CHECK_EQ(block_average(std::vector<double>(64, 2.5)).error, 0.0);
    CHECK_EQ(block_average(std::vector<double>(64, 2.5)).mean, 2.5);
    std::vector<double> alternating;
    for (int k = 0; k < 64; ++k) alternating.push_back(k % 2 == 0 ? 1.0 : -1.0);
    const MeanWithError a = block_average(alternating);
    CHECK_EQ(a.mean, 0.0);
    CHECK_EQ(a.error, 0.0);  // blocks of four: each averages to 0
    CHECK_EQ(a.blocks, std::size_t{16});
    // Independent uniform samples: the error is sigma / sqrt(n) = (1 / sqrt(12)) / 64.
    std::vector<double> uniform;
    std::uint64_t state = 12345;
    for (int k = 0; k < 4096; ++k) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        uniform.push_back(static_cast<double>(state >> 11) * 0x1p-53);
    }
    const MeanWithError u = block_average(uniform);
    CHECK_NEAR(u.mean, 0.5, 4.0 / std::sqrt(12.0) / 64.0);
    CHECK(u.error > 0.5 / std::sqrt(12.0) / 64.0 && u.error < 2.0 / std::sqrt(12.0) / 64.0);
    CHECK_EQ(block_average(std::vector<double>{1.0, 2.0}).blocks, std::size_t{0});
    // The same series at any power-of-two scale, up to next to the largest
    // double and down to the smallest normal ones: the same bits, scaled.
    const auto scaled_by = [&](int exponent, std::size_t count) {
        std::vector<double> scaled;
        for (std::size_t k = 0; k < count; ++k) scaled.push_back(std::ldexp(uniform[k] + 0.25, exponent));
        return block_average(scaled);
    };
    const MeanWithError unscaled = scaled_by(0, uniform.size()), few = scaled_by(0, 20);
    CHECK_EQ(few.blocks, std::size_t{0});  // too few for blocks: the mean alone
    for (const int exponent : {-1000, -300, 300, 1020}) {
        check::Context context("scaled by 2^", exponent);
        const MeanWithError s = scaled_by(exponent, uniform.size());
        CHECK_EQ(s.mean, std::ldexp(unscaled.mean, exponent));
        CHECK_EQ(s.error, std::ldexp(unscaled.error, exponent));
        CHECK_EQ(scaled_by(exponent, 20).mean, std::ldexp(few.mean, exponent));
    }
}

// A periodic box that drifts has the pressure of one at rest: kT counts the
// motion in the centre of mass's frame (with its 2N - 2 degrees of freedom).
void a_drifting_periodic_box_has_the_same_pressure() {
    // On paper: two disks moving together carry no heat (nothing to
    // measure: all zero); two moving apart at 1 have E = 1 and P = 0, so kT = 1.
    const World world{20.0, 1.0};
    const CollisionSums none{};
    const Pressure together = periodic_box_pressure(world, 2, 1.0, Vec2(2.0, 0.0), none, 1.0);
    CHECK_EQ(together.kT, 0.0);
    CHECK_EQ(together.Z, 0.0);
    // The same, its momentum's energy rounded a little above the kinetic
    // energy (as summing a pure drift's velocities may): all zero, kT too.
    const Pressure rounded = periodic_box_pressure(world, 2, 1.0, Vec2(2.0 + 1e-12, 0.0), none, 1.0);
    CHECK_EQ(rounded.kT, 0.0);
    CHECK_EQ(rounded.betaP_d2, 0.0);
    // No kinetic energy in a walled box: all zero.
    CHECK_EQ(walled_box_pressure(world, 5, 0.0, CollisionSums{1.0, 1.0}, 1.0).kT, 0.0);
    const Pressure apart = periodic_box_pressure(world, 2, 1.0, Vec2::Zero(), none, 1.0);
    CHECK_EQ(apart.kT, 1.0);
    CHECK_EQ(apart.Z, 1.0);  // no collisions: the ideal gas

    // A crystal's run in a periodic box, and the same run boosted by V: the
    // same collisions to rounding, the same kT and Z.
    SceneFamilyOptions options;
    options.particles = 120;
    options.area_fraction = 0.6;
    options.boundary = Boundary::periodic;
    const Scene scene = make_family_scene(SceneFamily::crystal, options);
    const Vec2 drift(0.7, -0.3);
    std::vector<Particle> boosted = scene.particles;
    for (Particle& p : boosted) p.velocity += drift;
    ExactOptions periodic;
    periodic.boundary = Boundary::periodic;
    ExactSimulation at_rest(scene.world, scene.particles, periodic);
    ExactSimulation drifting(scene.world, boosted, periodic);
    for (int s = 0; s < 3; ++s) {
        at_rest.step();
        drifting.step();
    }
    const auto pressure_of = [&](const ExactSimulation& engine) {
        return periodic_box_pressure(scene.world, scene.particles.size(), total_kinetic_energy(engine.particles()),
                                     total_momentum(engine.particles()), engine.collision_sums(), 3.0);
    };
    const Pressure rest = pressure_of(at_rest);
    const Pressure moving = pressure_of(drifting);
    check::Context context("Z at rest ", rest.Z, ", drifting ", moving.Z);
    CHECK(rest.Z > 1.5);  // a dense crystal: far from the ideal gas
    CHECK(std::abs(moving.kT - rest.kT) <= 1e-9 * rest.kT);
    CHECK(std::abs(moving.Z - rest.Z) <= 1e-9 * rest.Z);
    // The drift's momentum is the boosted state's, conserved by the box.
    const Vec2 momentum = total_momentum(drifting.particles());
    CHECK(std::abs(momentum.x() - 120 * 0.7) < 1e-9 && std::abs(momentum.y() + 120 * 0.3) < 1e-9);

    // simcli's observables file: the same Z for the drifting scene.
    const std::string simcli = SIMCLI_PATH;
    char dir_template[] = "/tmp/particlesim-drift-XXXXXX";
    const std::string dir = mkdtemp(dir_template);
    const auto z_column = [&](const std::vector<Particle>& particles, const std::string& name) {
        Scene written = scene;
        written.particles = particles;
        written.steps = 3;
        std::ostringstream text;
        write_scene(text, written);
        const std::string csv = dir + "/" + name + ".csv";
        const run_process::Result r = run_process::run(
            simcli, {"--engine", "exact", "--boundary", "periodic", "--observables", csv, "-o", "/dev/null"},
            text.str());
        CHECK_EQ(r.status, 0);
        std::istringstream rows(run_process::slurp(csv));
        std::string line;
        std::getline(rows, line);
        std::vector<double> z;
        while (std::getline(rows, line)) {
            std::istringstream fields(line);
            std::string field;
            for (int k = 0; k <= 6; ++k) std::getline(fields, field, ',');
            z.push_back(std::stod(field));
        }
        return z;
    };
    const std::vector<double> z_rest = z_column(scene.particles, "rest");
    const std::vector<double> z_moving = z_column(boosted, "moving");
    CHECK_EQ(z_rest.size(), 3U);
    CHECK_EQ(z_moving.size(), z_rest.size());
    for (std::size_t k = 0; k < std::min(z_rest.size(), z_moving.size()); ++k) {
        CHECK(z_rest[k] > 1.5);
        CHECK(std::abs(z_moving[k] - z_rest[k]) <= 1e-9 * z_rest[k]);
    }
    std::filesystem::remove_all(dir);
}

void simcli_observables_file() {
    const std::string simcli = SIMCLI_PATH;
    char dir_template[] = "/tmp/particlesim-observables-XXXXXX";
    const std::string dir = mkdtemp(dir_template);
    const std::string csv = dir + "/run.csv";
    const std::string scene = run_process::run(SIMGEN_PATH, {"gas", "-n", "200", "-s", "95", "--mode", "perf"}).out;
    const run_process::Result r = run_process::run(simcli,
                                                   {"--engine", "exact", "--observables", csv, "--observe-every", "10",
                                                    "--measure-from", "20", "--stats", "-o", "/dev/null"},
                                                   scene);
    CHECK_EQ(r.status, 0);
    std::istringstream rows(run_process::slurp(csv));
    std::string line;
    std::getline(rows, line);
    CHECK_EQ(line, std::string("step,time,pair_collisions,wall_collisions,kinetic_energy,betaP_d2,Z,psi6,"
                               "betaP_d2_walls,Z_walls"));
    std::vector<long> steps;
    while (std::getline(rows, line)) steps.push_back(std::stol(line));
    CHECK((steps == std::vector<long>{10, 20, 30, 40, 50, 60, 70, 80, 90, 95}));
    CHECK(r.err.find("stats: pressure beta P (2r)^2 = ") != std::string::npos);
    CHECK(r.err.find("blocks of the observables rows from step 20") != std::string::npos);
    CHECK(r.err.find("longer blocks") == std::string::npos);  // 8 rows: 4 blocks, nothing longer to compare
    // With 16 blocks, the error from 8 longer ones beside it.
    const run_process::Result many = run_process::run(simcli,
                                                      {"--engine", "exact", "--observables", csv, "--observe-every",
                                                       "1", "--measure-from", "20", "--stats", "-o", "/dev/null"},
                                                      scene);
    CHECK_EQ(many.status, 0);
    CHECK(many.err.find("; 16 blocks of the observables rows from step 20 (8 longer blocks: +- ") != std::string::npos);
    // Refused, exit 2, before anything runs.
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{"--observables", csv},
                                               {"--engine", "exact", "--observe-every", "3"},
                                               {"--engine", "exact", "--observables", csv, "--observe-every", "0"},
                                               {"--engine", "exact", "--observables", "/nonexistent/run.csv"},
                                               {"--engine", "exact", "--observables", csv, "--measure-from", "96"}}) {
        const run_process::Result refused = run_process::run(simcli, args, scene);
        CHECK_EQ(refused.status, 2);
        CHECK(refused.err.rfind("simcli: ", 0) == 0 && refused.err.find('\n') == refused.err.size() - 1);
    }
    std::remove(csv.c_str());
    rmdir(dir.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_observables",
                      {{"sums of hand-built collisions", sums_of_hand_built_collisions},
                       {"the two routes agree in a walled box", the_two_routes_agree_in_a_walled_box},
                       {"hexatic order of lattice and gas", hexatic_order_of_lattice_and_gas},
                       {"hexatic order against every pair", hexatic_order_against_every_pair},
                       {"what cannot be measured is refused", what_cannot_be_measured_is_refused},
                       {"block averages of known series", block_averages_of_known_series},
                       {"a drifting periodic box has the same pressure", a_drifting_periodic_box_has_the_same_pressure},
                       {"simcli observables file", simcli_observables_file}});
}
