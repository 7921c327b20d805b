// The exact engine in a periodic box: hand-built collisions across the edges
// worked out on paper; the same bytes as walls where nothing reaches an edge,
// and for every cell count; no overlap by the nearest image after any step,
// and the total momentum kept; a save restored bit for bit; the pressure of a
// gas at area fraction 0.3 against Henderson's equation of state; and simcli's
// --boundary.

#include "check.hpp"
#include "disk.hpp"
#include "run_process.hpp"
#include "state_hash.hpp"

#include "particlesim/exact_simulation.hpp"
#include "particlesim/observables.hpp"
#include "particlesim/scene_families.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace particlesim;
using test_scenes::disk;

namespace {

ExactOptions periodic(std::optional<int> cells = std::nullopt) {
    ExactOptions o;
    o.boundary = Boundary::periodic;
    o.cells_per_side = cells;
    return o;
}

void collisions_across_the_edges() {
    // Head on across x = 0: 3 apart through the edge, contact (2 apart) at
    // t = 0.5, back where they started, velocities swapped, after one step.
    ExactSimulation pair(World{20.0, 1.0}, {disk(1.5, 10, -1, 0), disk(18.5, 10, 1, 0)}, periodic());
    pair.step();
    CHECK_EQ(pair.totals().particle_collisions, std::uint64_t{1});
    CHECK_EQ(pair.totals().wall_collisions, std::uint64_t{0});
    CHECK(pair.particles()[0].position == Vec2(1.5, 10) && pair.particles()[0].velocity == Vec2(1, 0));
    CHECK(pair.particles()[1].position == Vec2(18.5, 10) && pair.particles()[1].velocity == Vec2(-1, 0));
    CHECK_NEAR(pair.collision_sums().pair_virial, 4.0, 1e-12);
    // Across the corner, along the diagonal: the images meet at t = 0.5.
    const double a = 1.5 / std::sqrt(2.0), b = 20.0 - a;  // 3 apart through the corner
    ExactSimulation corner(World{20.0, 1.0}, {disk(a, a, -1, -1), disk(b, b, 1, 1)}, periodic());
    corner.step();
    CHECK_EQ(corner.totals().particle_collisions, std::uint64_t{1});
    // A free disk goes round the box: every position wrapped into [0, L).
    ExactSimulation free_disk(World{20.0, 1.0}, {disk(19, 10, 1, 0.5)}, periodic());
    for (int s = 0; s < 20; ++s) free_disk.step();
    CHECK(free_disk.particles()[0].position == Vec2(19, 0));
    for (int s = 0; s < 7; ++s) free_disk.step();
    CHECK(free_disk.particles()[0].position == Vec2(6, 3.5));
}

Scene gas(std::size_t count, double fraction, std::uint64_t seed, double speed = 0.5) {
    SceneFamilyOptions o;
    o.particles = count;
    o.area_fraction = fraction;
    o.seed = seed;
    o.speeds = SpeedRange{speed, speed};
    return make_family_scene(SceneFamily::gas, o);
}

std::uint64_t run_hash(const World& world, const std::vector<Particle>& start, const ExactOptions& options, int steps) {
    ExactSimulation engine(world, start, options);
    for (int s = 0; s < steps; ++s) engine.step();
    return state_hash::hash(engine.particles());
}

void the_same_bytes_where_they_must_be() {
    // Disks in the middle of a large box, too slow to reach an edge or a wall.
    std::vector<Particle> middle;
    for (int k = 0; k < 60; ++k) {
        middle.push_back(disk(40.0 + 2.5 * (k % 8), 40.0 + 2.5 * (k / 8), 0.05 * std::sin(k), 0.05 * std::cos(3 * k)));
    }
    const World large{100.0, 1.0};
    CHECK_EQ(run_hash(large, middle, {}, 40), run_hash(large, middle, periodic(), 40));
    // Every cell count, the same events.
    const Scene dense = gas(300, 0.4, 7);
    const std::uint64_t five = run_hash(dense.world, dense.particles, periodic(5), 60);
    for (const int cells : {6, 9, 13}) {
        check::Context context(cells, " cells a side");
        CHECK_EQ(run_hash(dense.world, dense.particles, periodic(cells), 60), five);
    }
    CHECK_EQ(run_hash(dense.world, dense.particles, periodic(), 60), five);
}

void no_overlap_and_momentum_kept() {
    const Scene dense = gas(300, 0.5, 11);
    ExactSimulation engine(dense.world, dense.particles, periodic());
    const double side = dense.world.box_size, diameter_sq = 4.0 * dense.world.radius * dense.world.radius;
    const auto image = [side](double d) { return d > side / 2 ? d - side : d < -side / 2 ? d + side : d; };
    Vec2 start(0.0, 0.0);
    for (const Particle& p : engine.particles()) start += p.velocity;
    double closest = INFINITY;
    bool inside = true;
    for (int s = 0; s < 40; ++s) {
        engine.step();
        const auto particles = engine.particles();
        for (std::size_t i = 0; i < particles.size(); ++i) {
            for (int axis = 0; axis < 2; ++axis) {
                inside = inside && particles[i].position[axis] >= 0.0 && particles[i].position[axis] < side;
            }
            for (std::size_t j = i + 1; j < particles.size(); ++j) {
                const Vec2 d = particles[j].position - particles[i].position;
                closest = std::min(closest, (std::pow(image(d.x()), 2) + std::pow(image(d.y()), 2)) / diameter_sq);
            }
        }
    }
    Vec2 end(0.0, 0.0);
    for (const Particle& p : engine.particles()) end += p.velocity;
    CHECK(inside);
    CHECK(closest > 1.0 - 1e-9);
    CHECK(engine.totals().particle_collisions > 3000);
    CHECK((end - start).norm() < 1e-9);
}

void a_save_resumes_bit_for_bit() {
    const Scene dense = gas(200, 0.3, 5);
    ExactSimulation straight(dense.world, dense.particles, periodic());
    ExactSimulation first(dense.world, dense.particles, periodic());
    for (int s = 0; s < 30; ++s) straight.step();
    for (int s = 0; s < 13; ++s) first.step();
    std::stringstream saved;
    first.save(saved);
    ExactSimulation resumed = ExactSimulation::restore(dense.world, saved, periodic());
    for (int s = 13; s < 30; ++s) resumed.step();
    CHECK_EQ(state_hash::hash(resumed.particles()), state_hash::hash(straight.particles()));
}

void pressure_against_henderson() {
    // Z = (1 + eta^2 / 8) / (1 - eta)^2 (Henderson 1975; within about 0.3 % of
    // the simulations' values at eta = 0.3).
    const double eta = 0.3;
    const double henderson = (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta));
    const Scene scene = gas(400, eta, 3);
    ExactSimulation engine(scene.world, scene.particles, periodic());
    for (int s = 0; s < 200; ++s) engine.step();
    std::vector<double> z;
    CollisionSums before = engine.collision_sums();
    for (int s = 0; s < 2800; s += 10) {
        for (int k = 0; k < 10; ++k) engine.step();
        double kinetic = 0.0;
        for (const Particle& p : engine.particles()) kinetic += 0.5 * p.velocity.squaredNorm();
        z.push_back(periodic_box_pressure(scene.world, 400, kinetic, total_momentum(engine.particles()),
                                          engine.collision_sums() - before, 10.0)
                        .Z);
        before = engine.collision_sums();
    }
    const MeanWithError measured = block_average(z);
    check::Context context("Z = ", measured.mean, " +- ", measured.error, " against ", henderson);
    CHECK(measured.error > 0.0 && measured.error < 0.01);
    CHECK(std::abs(measured.mean - henderson) <= std::max(4.0 * measured.error, 0.005 * henderson));
}

void simcli_boundary() {
    const std::string simcli = SIMCLI_PATH;
    const std::string across = "2 20 1 1 print\n0 1.5 10 -1 0\n1 18.5 10 1 0\n";
    const run_process::Result r = run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"}, across);
    CHECK_EQ(r.status, 0);
    CHECK(r.out.find("1 0 1.50000000 10.00000000 1.00000000 0.00000000 1 0\n") != std::string::npos);
    const run_process::Result walls = run_process::run(simcli, {"--engine", "exact", "--boundary", "walls"}, across);
    CHECK(walls.out.find("1 0 1.50000000 10.00000000 1.00000000 0.00000000 0 1\n") != std::string::npos);
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--boundary", "periodic"}, {"--engine", "exact", "--boundary", "torus"}}) {
        const run_process::Result refused = run_process::run(simcli, args, across);
        CHECK_EQ(refused.status, 2);
        CHECK(refused.err.rfind("simcli: --boundary", 0) == 0);
    }
    // Its output judged by simcheck under the same rules; moved by 1e-3, not.
    char dir_template[] = "/tmp/particlesim-periodic-XXXXXX";
    const std::string dir = mkdtemp(dir_template);
    const std::string scene = run_process::run(SIMGEN_PATH, {"gas", "-n", "150", "--fraction", "0.4", "-s", "20"}).out;
    std::ofstream(dir + "/scene.in") << scene;
    const std::string trajectory = dir + "/run.xyz", observables = dir + "/run.csv", checkpoint = dir + "/run.ckpt";
    const run_process::Result run =
        run_process::run(simcli,
                         {"--engine", "exact", "--boundary", "periodic", "--trajectory", trajectory, "--observables",
                          observables, "--checkpoint", checkpoint, "--checkpoint-every", "7"},
                         scene);
    CHECK_EQ(run.status, 0);
    std::ofstream(dir + "/out.txt") << run.out;
    const run_process::Result judged = run_process::run(
        SIMCHECK_PATH, {"--engine", "exact", "--boundary", "periodic", dir + "/scene.in", dir + "/out.txt"});
    CHECK_EQ(judged.status, 0);
    CHECK(judged.out.find("continuous-time hard disks in a periodic box") != std::string::npos);
    std::string moved = run.out;
    const std::size_t at = moved.find("\n10 3 ") + 7;
    moved[at] = moved[at] == '9' ? '8' : static_cast<char>(moved[at] + 1);  // the integer part of x, step 10
    std::ofstream(dir + "/moved.txt") << moved;
    CHECK_EQ(run_process::run(SIMCHECK_PATH,
                              {"--engine", "exact", "--boundary", "periodic", dir + "/scene.in", dir + "/moved.txt"})
                 .status,
             1);
    CHECK(run_process::slurp(trajectory).find("pbc=\"T T F\"") != std::string::npos);
    CHECK(run_process::slurp(observables)
              .rfind("step,time,pair_collisions,wall_collisions,kinetic_energy,betaP_d2,Z,psi6\n", 0) == 0);
    // Resumed from its checkpoint (after step 14): the same last block.
    const run_process::Result resumed = run_process::run(simcli, {"--resume", checkpoint});
    CHECK_EQ(resumed.status, 0);
    const std::string last_block = run.out.substr(run.out.find("\n20 0 ") + 1);
    CHECK(resumed.out.size() >= last_block.size() &&
          resumed.out.compare(resumed.out.size() - last_block.size(), last_block.size(), last_block) == 0);
    // Centres closer than r to an edge: a periodic scene, not a walled one.
    const std::string near_edges = "2 20 1 3 print\n0 0.25 10 -1 0\n1 17.5 10 1 0.5\n";
    std::ofstream(dir + "/edges.in") << near_edges;
    const run_process::Result edges =
        run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"}, near_edges);
    CHECK_EQ(edges.status, 0);
    CHECK(edges.out.find("0 0 0.25000000 10.00000000") == 0);
    std::ofstream(dir + "/edges.out") << edges.out;
    CHECK_EQ(run_process::run(SIMCHECK_PATH,
                              {"--engine", "exact", "--boundary", "periodic", dir + "/edges.in", dir + "/edges.out"})
                 .status,
             0);
    // Printed disks that overlap across an edge: named as an overlap, 1.7 apart.
    std::ofstream(dir + "/across.in") << "2 20 1 1 print\n0 0.5 5 1 0\n1 18.5 5 1 0\n";
    std::ofstream(dir + "/across.out") << "0 0 0.50000000 5.00000000 1.00000000 0.00000000\n"
                                          "0 1 18.50000000 5.00000000 1.00000000 0.00000000\n"
                                          "1 0 1.50000000 5.00000000 1.00000000 0.00000000 0 0\n"
                                          "1 1 19.80000000 5.00000000 1.00000000 0.00000000 0 0\n";
    const run_process::Result overlapping = run_process::run(
        SIMCHECK_PATH, {"--engine", "exact", "--boundary", "periodic", dir + "/across.in", dir + "/across.out"});
    CHECK_EQ(overlapping.status, 1);
    CHECK(overlapping.out.rfind("step 1: particles 0 and 1 overlap: their centres are 1.7 apart", 0) == 0);
    // A disk that ends a step 2e-10 short of the edge is printed at 0: its
    // printed position lies in [0, L), simcheck takes it as the same place,
    // and the block reads back as a periodic scene.
    const std::string to_the_edge = "2 20 1 2 print\n0 10 5 4.9999999999 0\n1 10 15 0 0\n";
    std::ofstream(dir + "/edge.in") << to_the_edge;
    const run_process::Result edge =
        run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"}, to_the_edge);
    CHECK_EQ(edge.status, 0);
    CHECK(edge.out.find("\n2 0 0.00000000 5.00000000 5.00000000 0.00000000 0 0\n") != std::string::npos);
    std::ofstream(dir + "/edge.out") << edge.out;
    CHECK_EQ(run_process::run(SIMCHECK_PATH,
                              {"--engine", "exact", "--boundary", "periodic", dir + "/edge.in", dir + "/edge.out"})
                 .status,
             0);
    // So too a scene's own position 4e-10 short of the edge, printed at step 0.
    const std::string listed_at_the_edge = "2 20 1 1 print\n0 19.9999999996 5 0 0\n1 10 5 0 0\n";
    std::ofstream(dir + "/listed.in") << listed_at_the_edge;
    const run_process::Result listed =
        run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"}, listed_at_the_edge);
    CHECK(listed.out.rfind("0 0 0.00000000 5.00000000 0.00000000 0.00000000\n", 0) == 0);
    std::ofstream(dir + "/listed.out") << listed.out;
    CHECK_EQ(run_process::run(SIMCHECK_PATH,
                              {"--engine", "exact", "--boundary", "periodic", dir + "/listed.in", dir + "/listed.out"})
                 .status,
             0);
    // A disk that ends step 1 on the edge: simcheck's copies of it, moved
    // within the rounding, end either side of it, a hair apart, not a box.
    // Every step is judged, and in perf mode the final state too; a final
    // state half a unit off is caught.
    for (const std::string mode : {"print", "perf"}) {
        check::Context mode_context(mode, " mode, a disk ending step 1 on the edge");
        const std::string on_the_edge = "2 20 1 2 " + mode + "\n0 10 5 10 0\n1 10 15 0 0\n";
        std::ofstream(dir + "/on_edge.in") << on_the_edge;
        const std::string out =
            run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"}, on_the_edge).out;
        std::ofstream(dir + "/on_edge.out") << out;
        const run_process::Result judged_run = run_process::run(
            SIMCHECK_PATH, {"--engine", "exact", "--boundary", "periodic", dir + "/on_edge.in", dir + "/on_edge.out"});
        CHECK_EQ(judged_run.status, 0);
        CHECK(judged_run.out.find("steps judged") == std::string::npos);  // every step
        std::string off = out;
        const std::size_t at = off.find("\n2 0 10.00000000");
        CHECK(at != std::string::npos);
        off.replace(at + 5, 11, "10.50000000");
        std::ofstream(dir + "/on_edge_off.out") << off;
        CHECK_EQ(run_process::run(SIMCHECK_PATH, {"--engine", "exact", "--boundary", "periodic", dir + "/on_edge.in",
                                                  dir + "/on_edge_off.out"})
                     .status,
                 1);
    }
    const run_process::Result from_the_edge = run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"},
                                                               "2 20 1 1 print\n0 0.00000000 5 1 0\n1 10 15 0 0\n");
    CHECK_EQ(from_the_edge.status, 0);
    const run_process::Result walled = run_process::run(simcli, {"--engine", "exact"}, near_edges);
    CHECK_EQ(walled.status, 2);
    CHECK(walled.err.find("x = 0.25 is outside [1, 19]") != std::string::npos);
    std::filesystem::remove_all(dir);

    const run_process::Result small = run_process::run(simcli, {"--engine", "exact", "--boundary", "periodic"},
                                                       "2 8 1 1 print\n0 2 4 1 0\n1 6 4 0 0\n");
    CHECK_EQ(small.status, 2);
    // In the app's words: the library's class name that refused is left out.
    CHECK(small.err.rfind("simcli: <stdin>:1: a periodic box needs at least 5 cells a side, each wider than a contact "
                          "distance",
                          0) == 0);
    CHECK(small.err.find("): L must exceed 5 x 2.00") != std::string::npos);
    CHECK(small.err.find(", not 8\n") != std::string::npos);

    // A grid asked for in the library: from 5 cells a side to as many as the
    // contact distance leaves room for (L = 20, r = 1: 9).
    for (const int cells : {4, 10, 9, 5}) {
        check::Context context(cells, " cells a side");
        std::string why;
        try {
            ExactSimulation(World{20.0, 1.0}, {disk(2, 4, 1, 0), disk(6, 4, 0, 0)}, periodic(cells));
        } catch (const std::invalid_argument& e) {
            why = e.what();
        }
        if (cells == 4 || cells == 10) {
            CHECK(why.find("cells_per_side from 5 to 9 here, not " + std::to_string(cells)) != std::string::npos);
        } else {
            CHECK(why.empty());
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_periodic_box",
                      {{"collisions across the edges", collisions_across_the_edges},
                       {"the same bytes where they must be", the_same_bytes_where_they_must_be},
                       {"no overlap and momentum kept", no_overlap_and_momentum_kept},
                       {"a save resumes bit for bit", a_save_resumes_bit_for_bit},
                       {"pressure against henderson", pressure_against_henderson},
                       {"simcli boundary", simcli_boundary}});
}
