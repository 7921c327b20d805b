// The error metrics: the overlap count on scenes built by hand, the metrics
// of a run against itself (all zero) and against a known difference, and the
// stepped engine converging to the exact one as the substeps grow.

#include "check.hpp"

#include "measure/overlap_counter.hpp"
#include "particlesim/accuracy.hpp"
#include "particlesim/random_scene.hpp"

#include <cmath>

using namespace particlesim;

namespace {

Particle at(double x, double y) {
    Particle p;
    p.position = Vec2(x, y);
    return p;
}

void overlap_counter() {
    const World params{100.0, 1.0};
    OverlapCounter counter;
    // 0 and 1 overlap (1.5 apart), 2 touches 1 exactly (not an overlap), 3 is alone.
    std::vector<Particle> scene = {at(10, 10), at(11.5, 10), at(13.5, 10), at(50, 50)};
    CHECK_EQ(counter.count(scene, params), 2U);
    // A contact off by rounding is not an overlap.
    scene[2].position.x() = std::nextafter(13.5, 0.0);
    CHECK_EQ(counter.count(scene, params), 2U);
    // Across cell borders and in a corner: a cluster of three.
    const std::vector<Particle> corner = {at(99, 99), at(98, 98.5), at(97.5, 99), at(1, 1)};
    CHECK_EQ(counter.count(corner, params), 3U);
    // Coincident centres overlap; a lone particle never does.
    CHECK_EQ(counter.count(std::vector<Particle>{at(5, 5), at(5, 5)}, params), 2U);
    CHECK_EQ(counter.count(std::vector<Particle>{at(5, 5)}, params), 0U);
    // Many particles in one spot: every one of them overlaps.
    std::vector<Particle> pile(500, at(40, 40));
    for (std::size_t i = 0; i < pile.size(); ++i) pile[i].position.x() += 1e-3 * static_cast<double>(i);
    CHECK_EQ(counter.count(pile, params), 500U);
}

void metrics_by_hand() {
    const World params{100.0, 1.0};
    RunRecord exact;
    exact.steps = 10;
    exact.particle_count = 2;
    exact.particle_collisions = 40;
    exact.wall_collisions = 10;
    exact.checkpoints = {{1, {Vec2(10, 10), Vec2(20, 20)}}, {10, {Vec2(10, 10), Vec2(20, 20)}}};
    const AccuracyReport same = compare_to_exact(exact, exact, params);
    CHECK_EQ(same.particle_collision_rate_error, 0.0);
    CHECK_EQ(same.wall_collision_rate_error, 0.0);
    CHECK(same.position_error_at(1) == 0.0);

    RunRecord stepped = exact;
    stepped.particle_collisions = 30;                                 // -25 %
    stepped.wall_collisions = 11;                                     // +10 %
    stepped.overlapping_particle_steps = 5;                           // of 2 x 10 particle-steps
    stepped.checkpoints[0].positions = {Vec2(13, 14), Vec2(20, 20)};  // one off by 5: RMS 5 / sqrt(2)
    stepped.largest_energy_drift = 3e-16;
    const AccuracyReport report = compare_to_exact(stepped, exact, params);
    CHECK_NEAR(report.particle_collision_rate_error, -0.25, 1e-15);
    CHECK_NEAR(report.wall_collision_rate_error, 0.1, 1e-15);
    CHECK_NEAR(report.overlap_fraction, 0.25, 1e-15);
    CHECK_NEAR(report.position_error_at(1).value_or(-1.0), 5.0 / std::sqrt(2.0) / 100.0, 1e-15);
    CHECK(report.position_error_at(10) == 0.0);
    CHECK(!report.position_error_at(2).has_value());  // not a checkpoint
    CHECK_EQ(report.energy_drift, 3e-16);
}

void exact_against_itself() {
    const World params{200.0, 1.0};
    const std::vector<Particle> start = make_random_particles(300, params, {11, SpeedRange{0.5, 3.0}});
    ExactSimulation a(params, start);
    ExactSimulation b(params, start, {.cells_per_side = 1});
    const RunRecord ra = record_run(a, 30);
    const AccuracyReport report = compare_to_exact(ra, record_run(b, 30), params);
    CHECK(ra.particle_collisions > 100);
    CHECK_EQ(ra.overlapping_particle_steps, 0U);  // real hard disks never overlap
    CHECK_EQ(report.particle_collision_rate_error, 0.0);
    CHECK(report.position_error_at(10) == 0.0);
    CHECK(ra.largest_energy_drift <= 1e-13);
}

// rules.md: the stepped engine converges to the exact one as K grows. On a
// moderately dense box of slow disks (area fraction 0.12, speeds up to 2r a
// step), every error falls as K goes 1 -> 4 -> 16 -> 64, averaged over scenes.
void substeps_converge_to_exact() {
    const World params{100.0, 1.0};
    const int ks[] = {1, 4, 16, 64};
    double rate_error[4] = {};
    double wall_error[4] = {};
    double overlaps[4] = {};
    double position_1[4] = {};
    for (std::uint64_t seed = 0; seed < 4; ++seed) {
        const std::vector<Particle> start = make_random_particles(400, params, {seed, SpeedRange{0.2, 2.0}});
        ExactSimulation exact(params, start);
        const RunRecord truth = record_run(exact, 40);
        for (int k = 0; k < 4; ++k) {
            SteppedSimulation stepped(params, start, {.substeps = ks[k]});
            const AccuracyReport r = compare_to_exact(record_run(stepped, 40), truth, params);
            rate_error[k] += std::abs(r.particle_collision_rate_error);
            wall_error[k] += std::abs(r.wall_collision_rate_error);
            overlaps[k] += r.overlap_fraction;
            position_1[k] += r.position_error_at(1).value();
        }
    }
    for (int k = 0; k < 4; ++k) {
        std::printf(
            "K = %2d: |particle rate error| %.4f, |wall rate error| %.4f, overlaps %.2e, position after 1 step %.2e\n",
            ks[k], rate_error[k] / 4, wall_error[k] / 4, overlaps[k] / 4, position_1[k] / 4);
    }
    CHECK(rate_error[0] > 0.1 * 4);  // the step rules lose many collisions here
    for (int k = 1; k < 4; ++k) {
        CHECK(rate_error[k] < rate_error[k - 1]);
        CHECK(overlaps[k] < overlaps[k - 1]);
        CHECK(position_1[k] < position_1[k - 1]);
    }
    CHECK(rate_error[3] < 0.02 * 4);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_accuracy",
                      {{"overlap counter", overlap_counter},
                       {"metrics by hand", metrics_by_hand},
                       {"exact against itself", exact_against_itself},
                       {"substeps converge to exact", substeps_converge_to_exact}});
}
