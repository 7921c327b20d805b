// The tie rules, selection, and the rules' consequences on scenes built so
// that the outcome can be worked out by hand. L = 20, r = 1.

#include "check.hpp"
#include "disk.hpp"

#include "core/random.hpp"
#include "particlesim/stepped_simulation.hpp"
#include "stepped/step_pipeline.hpp"

#include <algorithm>
#include <limits>
#include <new>
#include <vector>

using namespace particlesim;

namespace {

const World params{20.0, 1.0};

Particle make(double x, double y, double vx, double vy) { return test_scenes::disk(x, y, vx, vy); }

void order_encodes_the_tie_rules() {
    const CandidateOrder order({});
    // Time first, walls before pairs at equal time, then the lowest indices.
    CHECK(order.before(Collision::pair(0.3, 3, 4), Collision::wall(0.5, 1)));
    CHECK(order.before(Collision::wall(0.5, 1), Collision::pair(0.5, 0, 2)));
    CHECK(order.before(Collision::pair(0.5, 0, 2), Collision::pair(0.5, 1, 2)));
    CHECK(order.before(Collision::pair(0.5, 0, 3), Collision::pair(0.5, 1, 2)));
    CHECK(order.before(Collision::wall(0.5, 0), Collision::wall(0.5, 1)));
    CHECK(!order.before(Collision::pair(0.5, 0, 2), Collision::pair(0.5, 0, 2)));
    // Stored out of the user's order, ties go by the user's indices: stored
    // places 0, 1, 2 hold user particles 2, 0, 1.
    const std::vector<std::uint32_t> user_index{2, 0, 1};
    const CandidateOrder stored(user_index);
    CHECK(stored.before(Collision::wall(0.5, 1), Collision::wall(0.5, 0)));
    CHECK(stored.before(Collision::pair(0.5, 1, 2), Collision::pair(0.5, 0, 1)));  // users (0, 1) before (0, 2)
    CHECK(stored.before(Collision::pair(0.4, 0, 1), Collision::pair(0.5, 1, 2)));  // time still first
}

void selection_is_the_greedy_pass() {
    // In order: (3, 4) at 0.3, the wall of 1 at 0.5, (0, 2) at 0.5 (found
    // twice by a search), (1, 2) at 0.5. (1, 2) loses: 1 already has its wall.
    std::vector<Collision> candidates{Collision::wall(0.5, 1)};
    std::vector<ThreadCandidates> found(2);
    found[0].found = {Collision::pair(0.5, 1, 2), Collision::pair(0.5, 0, 2)};
    found[1].found = {Collision::pair(0.3, 3, 4), Collision::pair(0.5, 0, 2)};
    std::vector<std::uint32_t> partner(5, no_collision);
    SelectionScratch scratch(5);
    std::vector<double> time(5, -1.0);
    const StepCounts counts = select_collisions(candidates, found, CandidateOrder({}), partner, time, scratch, 1);
    CHECK_EQ(counts.particle_collisions, 2U);
    CHECK_EQ(counts.wall_collisions, 1U);
    CHECK(partner == (std::vector<std::uint32_t>{2, wall_collision, 0, 4, 3}));
    CHECK(time == (std::vector<double>{0.5, 0.5, 0.5, 0.3, 0.3}));
    CHECK(scratch.earliest == std::vector<std::uint32_t>(5, no_collision));
    CHECK(candidates.empty());

    // A chain decided over rounds: (3, 4) at 0.1 comes first, so (2, 3) at
    // 0.2 is out, so (1, 2) at 0.3 is accepted, so (0, 1) at 0.4 is out; 5
    // is untouched.
    std::vector<Collision> chain{Collision::pair(0.4, 0, 1), Collision::pair(0.3, 1, 2), Collision::pair(0.2, 2, 3),
                                 Collision::pair(0.1, 3, 4)};
    std::vector<std::uint32_t> chain_partner(6, no_collision);
    SelectionScratch chain_scratch(6);
    std::vector<double> chain_time(6, -1.0);
    select_collisions(chain, {}, CandidateOrder({}), chain_partner, chain_time, chain_scratch, 1);
    CHECK(chain_partner == (std::vector<std::uint32_t>{no_collision, 2, 1, 4, 3, no_collision}));
}

// One random candidate set with many shared particles and exact ties, in
// the user's order or stored out of it (ties then go by the user's indices),
// spread over several threads' lists: does select_collisions, on `threads`
// threads, give every particle the partner of the greedy pass over the
// sorted candidates? `piled`: every pair a candidate at t = 0 too, as disks
// piled on one another make them (the lowest indices win, one pair a
// round: the rounds give way to a sorted walk).
bool selection_matches_greedy(SplitMix64& rng, std::uint32_t particles, int candidate_count, int threads,
                              bool piled = false) {
    std::vector<std::uint32_t> user_index(particles);
    for (std::uint32_t i = 0; i < particles; ++i) user_index[i] = i;
    const bool user_order = rng.next() % 2 == 0;
    if (!user_order) {
        for (std::uint32_t i = particles - 1; i > 0; --i) std::swap(user_index[i], user_index[rng.next() % (i + 1)]);
    }
    std::vector<Collision> walls;
    std::vector<ThreadCandidates> found(1 + rng.next() % 3);
    std::vector<Collision> all;
    for (int k = 0; k < candidate_count; ++k) {
        const double t = static_cast<double>(rng.next() % 8) / 8.0;  // many exact ties
        const auto i = static_cast<std::uint32_t>(rng.next() % particles);
        const auto j = static_cast<std::uint32_t>(rng.next() % particles);
        if (rng.next() % 4 == 0 || i == j) {
            walls.push_back(Collision::wall(t, i));
            all.push_back(walls.back());
        } else {
            all.push_back(Collision::pair(t, std::min(i, j), std::max(i, j)));
            found[rng.next() % found.size()].found.push_back(all.back());
        }
    }
    for (std::uint32_t i = 0; piled && i < particles; ++i) {
        for (std::uint32_t j = i + 1; j < particles; ++j) {
            all.push_back(Collision::pair(0.0, i, j));
            found[rng.next() % found.size()].found.push_back(all.back());
        }
    }
    // The rules' way, independently: rename to user indices, sort, walk.
    std::vector<Collision> sorted;
    for (Collision c : all) {
        c.i = user_index[c.i];
        if (c.kind == CollisionKind::pair) {
            c.j = user_index[c.j];
            if (c.i > c.j) std::swap(c.i, c.j);
        }
        sorted.push_back(c);
    }
    // Renamed to user indices, the stored order is the rules' order.
    std::sort(sorted.begin(), sorted.end(), [](const Collision& a, const Collision& b) { return comes_before(a, b); });
    std::vector<std::uint32_t> stored_of(particles);
    for (std::uint32_t i = 0; i < particles; ++i) stored_of[user_index[i]] = i;
    std::vector<std::uint32_t> expected(particles, no_collision);
    for (const Collision& c : sorted) {
        const std::uint32_t a = stored_of[c.i];
        if (expected[a] != no_collision) continue;
        if (c.kind == CollisionKind::wall) {
            expected[a] = wall_collision;
        } else if (const std::uint32_t b = stored_of[c.j]; expected[b] == no_collision) {
            expected[a] = b;
            expected[b] = a;
        }
    }
    std::vector<std::uint32_t> partner(particles, no_collision);
    SelectionScratch scratch(particles);
    std::vector<double> time(particles, 0.0);
    const CandidateOrder order(user_order ? std::span<const std::uint32_t>{} : std::span(user_index));
    select_collisions(walls, found, order, partner, time, scratch, threads);
    return partner == expected && scratch.earliest == std::vector<std::uint32_t>(particles, no_collision);
}

void selection_equals_greedy_on_random_candidates() {
    SplitMix64 rng(11);
    int wrong = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const std::uint32_t particles = 2 + static_cast<std::uint32_t>(rng.next() % 40);
        wrong += selection_matches_greedy(rng, particles, static_cast<int>(rng.next() % 80), 1) ? 0 : 1;
    }
    CHECK_EQ(wrong, 0);
}

// Enough candidates for the passes to run on several threads, which then
// claim the same particles at the same time.
void selection_equals_greedy_on_any_thread_count() {
    SplitMix64 rng(12);
    int wrong = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const std::uint32_t particles = 500 + static_cast<std::uint32_t>(rng.next() % 20000);
        const int candidates = 8192 + static_cast<int>(rng.next() % 40000);
        for (const int threads : {1, 2, 3, 4}) {
            SplitMix64 same = rng;
            wrong += selection_matches_greedy(same, particles, candidates, threads) ? 0 : 1;
        }
        rng.next();
    }
    CHECK_EQ(wrong, 0);
}

void selection_of_a_pile_is_the_greedy_pass() {
    SplitMix64 rng(13);
    int wrong = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const std::uint32_t particles = 50 + static_cast<std::uint32_t>(rng.next() % 400);
        for (const int threads : {1, 2}) {
            SplitMix64 same = rng;
            wrong +=
                selection_matches_greedy(same, particles, static_cast<int>(rng.next() % 2000), threads, true) ? 0 : 1;
        }
        rng.next();
    }
    CHECK_EQ(wrong, 0);
}

// A search's list of candidates grows up to its limit (by default an
// eighth of the machine's memory; here 5000 candidates' worth) and then
// refuses with std::bad_alloc, which simcli reports, instead of growing
// until the kernel kills the process.
void a_candidate_list_grows_within_its_limit() {
    ThreadCandidates list;
    list.most_bytes = 5000 * sizeof(Collision);
    std::size_t added = 0;
    bool refused = false;
    try {
        for (std::uint32_t k = 0; k < 20000; ++k) {
            list.add(Collision::pair(0.0, k, k + 1));
            ++added;
        }
    } catch (const std::bad_alloc&) {
        refused = true;
    }
    CHECK(refused);
    CHECK_EQ(added, std::size_t{5000});
    const std::size_t machine = ThreadCandidates::most_candidate_bytes();
    CHECK(machine >= (std::size_t{64} << 20));  // an eighth of at least 512 MB
    CHECK(machine < std::numeric_limits<std::size_t>::max());
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
int main(int argc, char** argv) {
    return check::run(argc, argv, "test_rules",
                      {{"order encodes the tie rules", order_encodes_the_tie_rules},
                       {"selection is the greedy pass", selection_is_the_greedy_pass},
                       {"selection equals greedy on random candidates", selection_equals_greedy_on_random_candidates},
                       {"selection equals greedy on any thread count", selection_equals_greedy_on_any_thread_count},
                       {"selection of a pile is the greedy pass", selection_of_a_pile_is_the_greedy_pass},
                       {"a candidate list grows within its limit", a_candidate_list_grows_within_its_limit},
                       {"wall beats pair at equal time", wall_beats_pair_at_equal_time},
                       {"lowest indices win among equal pairs", lowest_indices_win_among_equal_pairs},
                       {"collision near wall stops at wall then passes through",
                        collision_near_wall_stops_at_wall_then_passes_through},
                       {"overlapping and receding separate freely", overlapping_and_receding_separate_freely},
                       {"coincident centres never collide", coincident_centres_never_collide},
                       {"invalid scenes are refused", invalid_scenes_are_refused}});
}
