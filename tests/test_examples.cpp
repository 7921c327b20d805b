// Every hand-built scene in examples/ against its outcome worked out on paper
// (the derivations are in the comments). L = 20, r = 1: centres in [1, 19].

#include "check.hpp"

#include <optional>
#include "example_scenes.hpp"

#include "core/physics.hpp"

#include <cmath>

using namespace particlesim;

namespace {

double total_energy(const std::vector<Particle>& particles) {
    double sum = 0.0;
    for (const Particle& p : particles) sum += kinetic_energy(p);
    return sum;
}

void head_on() {
    // Centres 8 apart closing at 1 per step: after 5 steps 3 apart, so the
    // contact (distance 2) falls at t = 1 of step 6: x = 9 and 11, velocities
    // swap. Then they separate: after step 10, x = 9 - 2 = 7 and 11 + 2 = 13.
    const auto s = example_scenes::run(example_scenes::load("head_on.in"));
    CHECK_EQ(s[5][0].position.x(), 8.5);
    CHECK_EQ(s[6][0].position.x(), 9.0);
    CHECK_EQ(s[6][1].position.x(), 11.0);
    CHECK_EQ(s[6][0].velocity.x(), -0.5);
    CHECK_EQ(s[6][1].velocity.x(), 0.5);
    CHECK_EQ(s[10][0].position.x(), 7.0);
    CHECK_EQ(s[10][1].position.x(), 13.0);
    CHECK_EQ(s[10][0].particle_collisions, 1U);
    CHECK_EQ(s[10][1].particle_collisions, 1U);
}

void crossing() {
    // Relative start (6, -9), relative velocity (-0.5, 0.5): closest approach
    // |6*0.5 - 9*0.5| / sqrt(0.5) = 2.12 > 2, so the paths cross untouched.
    const auto s = example_scenes::run(example_scenes::load("crossing.in"));
    CHECK_EQ(s[20][0].position.x(), 14.0);
    CHECK_EQ(s[20][1].position.y(), 11.0);
    CHECK_EQ(s[20][0].particle_collisions + s[20][1].particle_collisions, 0U);
}

void newtons_cradle() {
    // 0 (x = 4, v = 0.5) meets 1 (x = 8) at t = 1 of step 4 and stops at 6.
    // Step 5: 1 touches 2 and approaches: collision at t = 0, 2 moves 0.5 to
    // 10.5, overlapping 3. Step 6: (2, 3) at t = 0, 3 to 12.5. Step 7: (3, 4)
    // at t = 0, 4 to 14.5, then 0.5 a step: 17 after step 12.
    const auto s = example_scenes::run(example_scenes::load("newtons_cradle.in"));
    CHECK_EQ(s[4][0].position.x(), 6.0);
    CHECK_EQ(s[4][1].velocity.x(), 0.5);
    CHECK_EQ(s[5][2].position.x(), 10.5);
    CHECK_EQ(s[5][1].velocity.x(), 0.0);
    CHECK_EQ(s[6][3].position.x(), 12.5);
    CHECK_EQ(s[7][4].position.x(), 14.5);
    const double expected_x[] = {6.0, 8.0, 10.5, 12.5, 17.0};
    const unsigned expected_pc[] = {1, 2, 2, 2, 1};
    for (int i = 0; i < 5; ++i) {
        CHECK_EQ(s[12][i].position.x(), expected_x[i]);
        CHECK_EQ(s[12][i].particle_collisions, expected_pc[i]);
        CHECK_EQ(s[12][i].velocity.x(), i == 4 ? 0.5 : 0.0);
    }
}

void glancing_line() {
    // 0 (y = 10, v = (0.8, 0)) meets 1 (offset 1.5 in y) with normal
    // (sqrt(1.75), 1.5) / 2 during step 4 (t = 3.35 from the start): the
    // exchange gives v0 = (0.45, -0.3969), v1 = (0.35, 0.3969). 1 then runs
    // along the normal into 2, placed 1.5 off that line: a second glancing hit.
    const auto s = example_scenes::run(example_scenes::load("glancing_line.in"));
    CHECK_EQ(s[3][0].particle_collisions, 0U);
    CHECK_NEAR(s[4][0].velocity.x(), 0.45, 1e-14);
    CHECK_NEAR(s[4][0].velocity.y(), -0.75 * 0.8 * std::sqrt(1.75) / 2.0, 1e-14);
    CHECK_NEAR(s[4][1].velocity.x(), 0.35, 1e-14);
    CHECK_EQ(s[16][1].particle_collisions, 2U);
    CHECK_EQ(s[16][2].particle_collisions, 1U);
    CHECK(s[16][2].velocity.norm() > 0.3);
    CHECK_NEAR(total_energy(s[16]), total_energy(s[0]), 1e-14);
}

void square() {
    // Four particles 4 from the centre moving in at 0.5. Neighbours meet when
    // sqrt(2) (4 - 0.5 t) = 2, t = 8 - 2 sqrt(2) = 5.17: during step 6, all
    // four pairs at the same time. The order (t, kind, i, j) takes (0, 2),
    // rejects (0, 3) and (1, 2), takes (1, 3). Each pair exchanges along its
    // diagonal normal: 0 leaves along +y, 2 along +x, 1 along -y, 3 along -x.
    const auto s = example_scenes::run(example_scenes::load("square.in"));
    for (int i = 0; i < 4; ++i) CHECK_EQ(s[6][i].particle_collisions, 1U);
    CHECK_NEAR(s[6][0].velocity.x(), 0.0, 1e-15);
    CHECK_NEAR(s[6][0].velocity.y(), 0.5, 1e-15);
    CHECK_NEAR(s[6][2].velocity.x(), 0.5, 1e-15);
    CHECK_NEAR(s[6][1].velocity.y(), -0.5, 1e-15);
    CHECK_NEAR(s[6][3].velocity.x(), -0.5, 1e-15);
    // The pairs are mirror images: the result keeps the symmetry.
    CHECK_NEAR(s[10][0].position.x() + s[10][1].position.x(), 20.0, 1e-12);
    CHECK_NEAR(total_energy(s[10]), total_energy(s[0]), 1e-14);
}

void triangle() {
    // Three particles 4 from the centre, 120 degrees apart, moving in at 0.5:
    // every pair meets when sqrt(3) (4 - 0.5 t) = 2, t = 5.69, during step 6.
    // Only one pair can collide in that step; the third particle goes on
    // unchanged (it may pass into the others: one collision per step).
    const auto s = example_scenes::run(example_scenes::load("triangle.in"));
    int collided = 0;
    int unchanged = 0;
    for (int i = 0; i < 3; ++i) {
        collided += s[6][i].particle_collisions == 1 ? 1 : 0;
        unchanged += s[6][i].velocity == s[5][i].velocity ? 1 : 0;
        CHECK_EQ(s[5][i].particle_collisions, 0U);
    }
    CHECK_EQ(collided, 2);
    CHECK_EQ(unchanged, 1);
    CHECK_NEAR(total_energy(s[10]), total_energy(s[0]), 1e-14);
}

void corner() {
    // From (17, 17) at (0.5, 0.5): tx = ty = 1 in step 4, a corner hit: both
    // components flip, wc = 1, and two steps back to (18, 18).
    const auto s = example_scenes::run(example_scenes::load("corner.in"));
    CHECK_EQ(s[4][0].position, Vec2(19, 19));
    CHECK_EQ(s[4][0].velocity, Vec2(-0.5, -0.5));
    CHECK_EQ(s[6][0].position, Vec2(18, 18));
    CHECK_EQ(s[6][0].wall_collisions, 1U);
}

void faster_than_box() {
    // x = 10, vx = 50 (the box is 18 wide): bounce on 19 at t = 0.18, then the
    // rest of the step stops at x = 1 (velocity kept, -50). Every later step
    // bounces at t = 0 and crosses the box to stop at the other wall.
    const auto s = example_scenes::run(example_scenes::load("faster_than_box.in"));
    for (int step = 1; step <= 5; ++step) {
        const bool odd = step % 2 == 1;
        CHECK_EQ(s[step][0].position.x(), odd ? 1.0 : 19.0);
        CHECK_EQ(s[step][0].velocity.x(), odd ? -50.0 : 50.0);
        CHECK_EQ(s[step][0].wall_collisions, static_cast<unsigned>(step));
    }
}

void every_search_agrees_on_examples() {
    for (const char* name : {"head_on.in", "crossing.in", "newtons_cradle.in", "glancing_line.in", "square.in",
                             "triangle.in", "corner.in", "faster_than_box.in"}) {
        const Scene scene = example_scenes::load(name);
        const auto brute = example_scenes::run(scene, {.pair_search = PairSearch::brute_force, .threads = 1});
        for (int grid : {0, 1, 2, 4, 7}) {
            const std::optional<int> cells = grid > 0 ? std::optional<int>(grid) : std::nullopt;
            const auto fast =
                example_scenes::run(scene, {.pair_search = PairSearch::grid, .grid_cells = cells, .threads = 2});
            bool same = true;
            for (std::size_t s = 0; s < brute.size(); ++s) {
                for (std::size_t i = 0; i < brute[s].size(); ++i) {
                    same = same && brute[s][i].position == fast[s][i].position &&
                           brute[s][i].velocity == fast[s][i].velocity &&
                           brute[s][i].particle_collisions == fast[s][i].particle_collisions;
                }
            }
            CHECK(same);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_examples",
                      {{"head on", head_on},
                       {"crossing", crossing},
                       {"newtons cradle", newtons_cradle},
                       {"glancing line", glancing_line},
                       {"square", square},
                       {"triangle", triangle},
                       {"corner", corner},
                       {"faster than box", faster_than_box},
                       {"every search agrees on examples", every_search_agrees_on_examples}});
}
