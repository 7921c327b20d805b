// The tie rules, selection, and the rules' consequences on scenes built so
// that the outcome can be worked out by hand. L = 20, r = 1.

#include "check.hpp"

#include "particlesim/stepped_simulation.hpp"
#include "random.hpp"
#include "step_pipeline.hpp"

#include <algorithm>
#include <vector>

using namespace particlesim;

namespace {

const World params{20.0, 1.0};

Particle make(double x, double y, double vx, double vy) {
    Particle p;
    p.position = Vec2(x, y);
    p.velocity = Vec2(vx, vy);
    return p;
}

void order_encodes_the_tie_rules() {
    std::vector<Collision> candidates{Collision::pair(0.5, 1, 2), Collision::wall(0.5, 1), Collision::pair(0.5, 0, 2),
                                      Collision::pair(0.3, 3, 4), Collision::pair(0.5, 0, 2)};
    std::vector<ThreadCandidates> none(1);
    std::vector<Collision> scratch;
    order_candidates(candidates, none, scratch, {}, {}, 1);
    // Sorted by time, walls before pairs at equal time, then by indices; the
    // duplicate (0, 2) found twice by a search is kept once.
    const std::vector<Collision> expected{Collision::pair(0.3, 3, 4), Collision::wall(0.5, 1),
                                          Collision::pair(0.5, 0, 2), Collision::pair(0.5, 1, 2)};
    CHECK(candidates == expected);

    std::vector<std::uint32_t> collision_of(5, 0);
    std::vector<Collision> accepted;
    select_collisions(candidates, collision_of, accepted);
    // (1, 2) loses: 1 already has its wall collision.
    const std::vector<Collision> expected_accepted{Collision::pair(0.3, 3, 4), Collision::wall(0.5, 1),
                                                   Collision::pair(0.5, 0, 2)};
    CHECK(accepted == expected_accepted);
    // Each particle is marked with its collision's number in `accepted`.
    CHECK(collision_of == (std::vector<std::uint32_t>{3, 2, 3, 1, 1}));
}

void wall_beats_pair_at_equal_time() {
    // 0 reaches x = 19 at t = 1; at that moment 1, sliding down x = 19, is at
    // distance 2 above it: a wall and a pair candidate at t = 1. The wall wins.
    SteppedSimulation sim(params, {make(17, 10, 2, 0), make(19, 13, 0, -1)});
    sim.step();
    const auto p = sim.particles();
    CHECK_EQ(p[0].wall_collisions, 1U);
    CHECK_EQ(p[0].particle_collisions, 0U);
    CHECK_EQ(p[0].velocity.x(), -2.0);
    CHECK_EQ(p[1].particle_collisions, 0U);
    CHECK_EQ(p[1].position.y(), 12.0);
}

void lowest_indices_win_among_equal_pairs() {
    // 1 at the centre, 0 and 2 at the same distance on either side closing at
    // the same speed: (0, 1) and (1, 2) tie at t = 0.5; (0, 1) wins and 2
    // passes on into 1.
    SteppedSimulation sim(params, {make(7, 10, 2, 0), make(10, 10, 0, 0), make(13, 10, -2, 0)});
    sim.step();
    const auto p = sim.particles();
    CHECK_EQ(p[0].particle_collisions, 1U);
    CHECK_EQ(p[1].particle_collisions, 1U);
    CHECK_EQ(p[2].particle_collisions, 0U);
    CHECK_EQ(p[2].position.x(), 11.0);  // free: 13 - 2, overlapping 1
}

void collision_near_wall_stops_at_wall_then_passes_through() {
    // Step 1: 0 (x = 15, v = 3) meets 1 (x = 17.5) at t = 1/6; 1 takes v = 3
    // and would travel 2.5 in the rest of the step, but stops at x = 19 after
    // 0.5 (velocity kept). Step 2: 1 bounces at t = 0 (the pair recedes at the
    // start of the step, so it is no candidate) and runs back through 0 (at
    // x = 15.5), ending at x = 16, overlapping. Step 3: overlapping and
    // approaching: collision at t = 0, velocities exchanged.
    SteppedSimulation sim(params, {make(15, 10, 3, 0), make(17.5, 10, 0, 0)});
    sim.step();
    auto p = sim.particles();
    CHECK_EQ(p[1].position.x(), 19.0);
    CHECK_EQ(p[1].velocity.x(), 3.0);
    CHECK_EQ(p[1].wall_collisions, 0U);
    CHECK_EQ(p[0].position.x(), 15.5);
    sim.step();
    p = sim.particles();
    CHECK_EQ(p[1].wall_collisions, 1U);
    CHECK_EQ(p[1].particle_collisions, 1U);
    CHECK_EQ(p[1].position.x(), 16.0);
    sim.step();
    p = sim.particles();
    CHECK_EQ(p[1].particle_collisions, 2U);
    CHECK_EQ(p[0].velocity.x(), -3.0);
    CHECK_EQ(p[1].velocity.x(), 0.0);
}

void overlapping_and_receding_separate_freely() {
    SteppedSimulation sim(params, {make(9.5, 10, -0.5, 0), make(10.5, 10, 0.5, 0)});
    particlesim::run(sim, 3);
    const auto p = sim.particles();
    CHECK_EQ(p[0].particle_collisions + p[1].particle_collisions, 0U);
    CHECK_EQ(p[0].position.x(), 8.0);
    CHECK_EQ(p[1].position.x(), 12.0);
}

void coincident_centres_never_collide() {
    SteppedSimulation sim(params, {make(10, 10, 1, 0), make(10, 10, 0, 1)});
    sim.step();
    const auto p = sim.particles();
    CHECK_EQ(p[0].particle_collisions, 0U);
    CHECK_EQ(p[0].position, Vec2(11, 10));
    CHECK_EQ(p[1].position, Vec2(10, 11));
}

void invalid_scenes_are_refused() {
    bool refused = false;
    try {
        SteppedSimulation sim(params, {make(0.5, 10, 0, 0)});
    } catch (const std::invalid_argument&) {
        refused = true;
    }
    CHECK(refused);
}

}  // namespace

// Busy steps sort in parallel parts and merge them: the result must be the
// one sorted, duplicate-free list, whatever the thread count. Times are drawn
// from few values, so ties and duplicates straddle the parts.
void parallel_order_equals_one_sort() {
    SplitMix64 rng(11);
    std::vector<Collision> drawn;
    for (int k = 0; k < 150000; ++k) {
        const double time = static_cast<double>(rng.next() % 64) / 64.0;
        const auto i = static_cast<std::uint32_t>(rng.next() % 500);
        drawn.push_back(rng.next() % 3 == 0
                            ? Collision::wall(time, i)
                            : Collision::pair(time, i, i + 1 + static_cast<std::uint32_t>(rng.next() % 3)));
    }
    std::vector<Collision> expected = drawn;
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    for (const int threads : {1, 2, 3, 8}) {
        // Half as walls already in the list, half as found by the threads.
        std::vector<Collision> candidates(drawn.begin(), drawn.begin() + 75000);
        std::vector<ThreadCandidates> found(static_cast<std::size_t>(threads));
        for (std::size_t k = 75000; k < drawn.size(); ++k) found[k % found.size()].found.push_back(drawn[k]);
        std::vector<Collision> scratch;
        order_candidates(candidates, found, scratch, {}, {}, threads);
        CHECK(candidates == expected);
    }
}

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_rules",
                      {{"order encodes the tie rules", order_encodes_the_tie_rules},
                       {"parallel order equals one sort", parallel_order_equals_one_sort},
                       {"wall beats pair at equal time", wall_beats_pair_at_equal_time},
                       {"lowest indices win among equal pairs", lowest_indices_win_among_equal_pairs},
                       {"collision near wall stops at wall then passes through",
                        collision_near_wall_stops_at_wall_then_passes_through},
                       {"overlapping and receding separate freely", overlapping_and_receding_separate_freely},
                       {"coincident centres never collide", coincident_centres_never_collide},
                       {"invalid scenes are refused", invalid_scenes_are_refused}});
}
