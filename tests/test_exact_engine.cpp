// The exact engine: hand-built scenes worked out on paper, the same events
// for every cell size, the stepped engine's agreement where the step rules
// are exact, and what it refuses.

#include "check.hpp"
#include "example_scenes.hpp"
#include "random_scenes.hpp"
#include "state_hash.hpp"

#include "particlesim/accuracy.hpp"
#include "particlesim/exact_simulation.hpp"
#include "particlesim/random_scene.hpp"
#include "particlesim/scene_families.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <cmath>
#include <optional>
#include <utility>

using namespace particlesim;

namespace {

// The states agree to well within printing precision (1e-8), with the same
// counters. (Bits differ: one engine adds v each step, the other v t once.)
bool agree(std::span<const Particle> a, std::span<const Particle> b) {
    bool same = a.size() == b.size();
    for (std::size_t i = 0; same && i < a.size(); ++i) {
        same = (a[i].position - b[i].position).lpNorm<Eigen::Infinity>() <= 1e-9 &&
               (a[i].velocity - b[i].velocity).lpNorm<Eigen::Infinity>() <= 1e-9 &&
               a[i].particle_collisions == b[i].particle_collisions && a[i].wall_collisions == b[i].wall_collisions;
    }
    return same;
}

void wall_then_pair() {
    // A at x = 95 moving +8, B at 93 at rest (touching, A receding), L = 100.
    // Exact: A reaches x = 99 at t = 0.5 and turns; it is back at 95, touching
    // B, at t = 1: head-on exchange, A stops, B leaves at -8. Step 2: B to 85.
    const Scene scene = example_scenes::load("wall_then_pair.in");
    const auto exact = example_scenes::run_exact(scene);
    CHECK_EQ(exact[1][0].position.x(), 95.0);
    CHECK_EQ(exact[1][0].velocity.x(), 0.0);
    CHECK_EQ(exact[1][1].position.x(), 93.0);
    CHECK_EQ(exact[1][1].velocity.x(), -8.0);
    CHECK_EQ(exact[1][0].wall_collisions, 1U);
    CHECK_EQ(exact[1][0].particle_collisions, 1U);
    CHECK_EQ(exact[2][1].position.x(), 85.0);
    // The step rules allow one collision per step: A bounces and ends the step
    // at 95 touching B, still moving at -8; they collide at t = 0 of step 2,
    // which gives the same state after step 2.
    const auto stepped = example_scenes::run(scene);
    CHECK_EQ(stepped[1][0].velocity.x(), -8.0);
    CHECK_EQ(stepped[1][0].particle_collisions, 0U);
    CHECK_EQ(stepped[1][1].velocity.x(), 0.0);
    CHECK_EQ(state_hash::hash(stepped[2]), state_hash::hash(exact[2]));
    // Two substeps of 0.5 catch both events in step 1, as the exact engine does.
    const auto substeps = example_scenes::run(scene, {.threads = 1, .substeps = 2});
    CHECK_EQ(state_hash::hash(substeps[1]), state_hash::hash(exact[1]));
}

void hand_built_examples() {
    // Scenes with at most one event per particle per step give the same
    // states in both engines (test_examples works them out on paper).
    for (const char* name : {"head_on.in", "crossing.in", "glancing_line.in", "corner.in"}) {
        const Scene scene = example_scenes::load(name);
        const auto exact = example_scenes::run_exact(scene);
        const auto stepped = example_scenes::run(scene);
        for (std::size_t s = 0; s < exact.size(); ++s) CHECK(agree(exact[s], stepped[s]));
    }
    // Newton's cradle: the exact engine passes the momentum down the whole
    // line at once (t = 1 of step 4); the stepped one takes a step per disk.
    const Scene cradle = example_scenes::load("newtons_cradle.in");
    const auto exact = example_scenes::run_exact(cradle);
    CHECK_EQ(exact[4][0].velocity.x(), 0.0);
    CHECK_EQ(exact[4][4].velocity.x(), 0.5);
    CHECK_EQ(exact[4][4].position.x(), 14.0);
    CHECK_EQ(exact[12][4].position.x(), 18.0);  // 14 + 0.5 x 8; the wall at 19 comes at t = 14
    CHECK_EQ(exact[12][4].wall_collisions, 0U);
    for (int i = 0; i < 4; ++i) CHECK_EQ(exact[12][static_cast<std::size_t>(i)].velocity.x(), 0.0);
}

void same_events_for_every_cell_size() {
    int compared = 0;
    for (std::uint64_t k = 0; k < 60; ++k) {
        // The family's non-overlapping regimes: 0 (default speeds) and 3 (slow).
        const NamedScene scene = random_scenes::make(k * 5 + (k % 2 == 0 ? 0 : 3));
        ExactSimulation automatic(scene.world, scene.particles);
        ExactSimulation one_cell(scene.world, scene.particles, {1});
        ExactSimulation seven(scene.world, scene.particles, {7});
        ExactSimulation seven_looking_ahead(scene.world, scene.particles, {7, std::nullopt, true});
        for (std::int64_t s = 0; s < scene.steps; ++s) {
            automatic.step();
            one_cell.step();
            seven.step();
            seven_looking_ahead.step();
            const std::uint64_t h = state_hash::hash(automatic.particles());
            CHECK_EQ(state_hash::hash(one_cell.particles()), h);
            CHECK_EQ(state_hash::hash(seven.particles()), h);
            CHECK_EQ(state_hash::hash(seven_looking_ahead.particles()), h);
        }
        CHECK_EQ(seven_looking_ahead.events_processed(), seven.events_processed());
        CHECK_EQ(automatic.totals().particle_collisions, one_cell.totals().particle_collisions);
        compared += automatic.totals().particle_collisions > 0 ? 1 : 0;
    }
    CHECK(compared >= 20);  // the comparison saw collisions
}

// A start that crowds the cells (Newton's cradle: a row of touching disks,
// as many to a cell of an even spread's grid as fit along it) gets a finer
// grid than its count alone calls for, and the same events for far fewer
// pair tests.
void crowded_starts_refine_the_cells() {
    SceneFamilyOptions row;
    row.particles = 2000;
    const Scene cradle = make_family_scene(SceneFamily::cradle, row);
    const int four_a_cell = static_cast<int>(std::ceil(std::sqrt(2000.0 / 4.0)));  // an even spread's grid
    ExactSimulation refined(cradle.world, cradle.particles);
    ExactSimulation even(cradle.world, cradle.particles, {.cells_per_side = four_a_cell});
    check::Context context("cells a side ", refined.cells_per_side(), " against ", four_a_cell);
    CHECK(refined.cells_per_side() >= 8 * four_a_cell);
    for (int k = 0; k < 10; ++k) {
        refined.step();
        even.step();
        CHECK_EQ(state_hash::hash(refined.particles()), state_hash::hash(even.particles()));
    }
    check::Context tests("pair tests ", refined.totals().pair_tests, " against ", even.totals().pair_tests);
    CHECK(refined.totals().pair_tests * 8 < even.totals().pair_tests);
}

// The look ahead only prefetches: on or off, in a scene large enough to
// have it on by default (a dense gas: events of every kind, many stale
// pair predictions), the same events and states.
void look_ahead_changes_no_event() {
    SceneFamilyOptions options;
    options.particles = 40000;
    options.area_fraction = 0.3;
    options.speeds = SpeedRange{0.1, 1.0};
    const Scene scene = make_family_scene(SceneFamily::gas, options);
    ExactSimulation automatic(scene.world, scene.particles);
    ExactSimulation without(scene.world, scene.particles, {std::nullopt, std::nullopt, false});
    for (int s = 0; s < 6; ++s) {
        automatic.step();
        without.step();
        CHECK_EQ(state_hash::hash(automatic.particles()), state_hash::hash(without.particles()));
    }
    CHECK_EQ(automatic.events_processed(), without.events_processed());
    CHECK(automatic.totals().particle_collisions > 20000U);
}

// The state is made when asked for: a run read only at its end, or every
// few steps, reads what a run read at every step does, both boundaries.
void state_read_late_is_the_state_read_every_step() {
    for (const Boundary boundary : {Boundary::walls, Boundary::periodic}) {
        for (std::uint64_t k = 0; k < 16; ++k) {
            const NamedScene scene = random_scenes::make(5 * (k / 2) + 3 * (k % 2));  // the regimes without overlaps
            ExactOptions options;
            options.boundary = boundary;
            ExactSimulation every(scene.world, scene.particles, options);
            ExactSimulation late(scene.world, scene.particles, options);
            CHECK_EQ(state_hash::hash(every.particles()), state_hash::hash(late.particles()));
            for (int s = 1; s <= 12; ++s) {
                every.step();
                const std::uint64_t read_every = state_hash::hash(every.particles());
                late.step();
                if (s % 5 == 0 || s == 12) CHECK_EQ(state_hash::hash(late.particles()), read_every);
            }
        }
    }
}

// The two calendar queues (linked buckets for small scenes, two tiers with
// the look ahead for large ones) forced both ways on every family, both
// boundaries where the family has them: the same states after every step
// and the same events, ties of the `ties` family included.
void both_queues_give_the_same_events() {
    int compared = 0;
    for (const SceneFamilyInfo& info : scene_families()) {
        for (const Boundary boundary : {Boundary::walls, Boundary::periodic}) {
            const bool has_boundary = info.family == SceneFamily::crystal || info.family == SceneFamily::compressed;
            if (boundary == Boundary::periodic && !has_boundary) continue;
            for (std::uint64_t seed = 1; seed <= 3; ++seed) {
                SceneFamilyOptions options;
                if (info.family != SceneFamily::ties) options.particles = 150;
                options.seed = seed;
                options.boundary = boundary;
                if (info.family == SceneFamily::crystal || info.family == SceneFamily::compressed)
                    options.area_fraction = 0.5;
                const Scene scene = make_family_scene(info.family, options);
                ExactOptions linked;
                linked.look_ahead = false;
                linked.boundary = boundary;
                ExactOptions ladder = linked;
                ladder.look_ahead = true;
                ExactSimulation small(scene.world, scene.particles, linked);
                ExactSimulation large(scene.world, scene.particles, ladder);
                for (int s = 0; s < 12; ++s) {
                    small.step();
                    large.step();
                    CHECK_EQ(state_hash::hash(small.particles()), state_hash::hash(large.particles()));
                }
                CHECK_EQ(small.events_processed(), large.events_processed());
                compared += small.totals().particle_collisions > 0 ? 1 : 0;
            }
        }
    }
    CHECK(compared >= 30);
}

// Worked out on paper: disks at x = 6 and 14 (y = 10, L = 20, r = 1) meet
// head-on at t = 3 (x = 9 and 11), then reach the walls at t = 11. One cell:
// 3 events (the pair, two walls). 4 x 4 cells of side 5: each disk also
// crosses a cell border (x = 5 and 15) at t = 7, 5 events.
void counts_events() {
    const World world{20.0, 1.0};
    std::vector<Particle> head_on(2);
    head_on[0].position = Vec2(6, 10);
    head_on[0].velocity = Vec2(1, 0);
    head_on[1].position = Vec2(14, 10);
    head_on[1].velocity = Vec2(-1, 0);
    ExactSimulation one_cell(world, head_on, {1});
    ExactSimulation sixteen_cells(world, head_on, {4});
    for (int s = 0; s < 11; ++s) {
        one_cell.step();
        sixteen_cells.step();
    }
    CHECK_EQ(one_cell.totals().particle_collisions, 1U);
    CHECK_EQ(one_cell.totals().wall_collisions, 2U);
    CHECK_EQ(one_cell.events_processed(), 3U);
    CHECK_EQ(sixteen_cells.events_processed(), 5U);
    CHECK_EQ(state_hash::hash(sixteen_cells.particles()), state_hash::hash(one_cell.particles()));
}

// rules.md: where no two events share a particle within a step, the step
// rules are exact; the engines agree to printing precision (1e-8).
void agrees_with_stepped_engine_when_events_do_not_share_a_particle() {
    std::uint64_t compared_steps = 0;
    std::uint64_t compared_collisions = 0;
    for (std::uint64_t seed = 0; seed < 200; ++seed) {
        const World params{60.0, 1.0};
        const std::vector<Particle> start = make_random_particles(12, params, {seed, SpeedRange{0.5, 4.0}});
        ExactSimulation exact(params, start);
        SteppedSimulation stepped(params, start);
        for (std::int64_t s = 0; s < 12; ++s) {
            exact.step();
            stepped.step();
            if (exact.last_step_particles_with_several_events() != 0) break;
            const bool same = agree(exact.particles(), stepped.particles());
            CHECK(same);
            if (!same)
                std::fprintf(stderr, "  seed %llu, step %lld\n", static_cast<unsigned long long>(seed),
                             static_cast<long long>(s + 1));
            ++compared_steps;
            compared_collisions += exact.last_step().particle_collisions + exact.last_step().wall_collisions;
        }
    }
    CHECK(compared_steps >= 500);
    CHECK(compared_collisions >= 500);
}

void conserves_and_stays_inside() {
    for (std::uint64_t k = 0; k < 30; ++k) {
        const NamedScene scene = random_scenes::make(k * 5 + (k % 2 == 0 ? 0 : 3));
        ExactSimulation exact(scene.world, scene.particles);
        const double e0 = total_kinetic_energy(exact.particles());
        Vec2 momentum0 = Vec2::Zero();
        for (const Particle& p : exact.particles()) momentum0 += p.velocity;
        particlesim::run(exact, scene.steps, [&](std::int64_t, std::span<const Particle> particles) {
            bool inside = true;
            for (const Particle& p : particles) {
                inside = inside && p.position.allFinite() && p.position.minCoeff() >= scene.world.lower() &&
                         p.position.maxCoeff() <= scene.world.upper();
            }
            CHECK(inside);
            CHECK(std::abs(relative_energy_drift(e0, total_kinetic_energy(particles))) <= 1e-12);
        });
    }
}

// The pair OverlappingStart names for a start, or none when it is not thrown.
std::optional<std::pair<std::uint32_t, std::uint32_t>> named_overlap(const World& world,
                                                                     const std::vector<Particle>& start) {
    try {
        ExactSimulation exact(world, start);
    } catch (const OverlappingStart& e) {
        return std::pair{e.first(), e.second()};
    }
    return std::nullopt;
}

void refuses_overlaps_and_bad_scenes() {
    const World params{20.0, 1.0};
    std::vector<Particle> pair(2);
    pair[0].position = Vec2(5, 5);
    pair[1].position = Vec2(6.5, 5);
    const std::pair<std::uint32_t, std::uint32_t> first_and_second(0, 1);
    CHECK(named_overlap(params, pair) == first_and_second);
    // Two overlapping pairs: the one with the lowest index is named, though
    // the other lies in an earlier cell (the search goes cell by cell first).
    std::vector<Particle> two_pairs(4);
    two_pairs[0].position = Vec2(15, 15);
    two_pairs[1].position = Vec2(5, 5);
    two_pairs[2].position = Vec2(15.5, 15);
    two_pairs[3].position = Vec2(5.5, 5);
    const std::pair<std::uint32_t, std::uint32_t> first_and_third(0, 2);
    CHECK(named_overlap(params, two_pairs) == first_and_third);
    pair[1].position = Vec2(7, 5);  // touching is allowed
    ExactSimulation touching(params, pair);
    CHECK_EQ(touching.particles().size(), 2U);
    // In a box of 2^50 r a coordinate near the middle is known to 1/8 r
    // (2^-51 L is four units in its last place): a contact two units closer
    // than 2r is touching, one five units closer an overlap.
    const World vast{0x1p50, 1.0};
    std::vector<Particle> far_out(2);
    far_out[0].position = Vec2(0x1p49 + 0.5, 0x1p49);
    far_out[1].position = Vec2(0x1p49 + 0.5 + 2.0 - 0.25, 0x1p49);
    CHECK(!named_overlap(vast, far_out));
    far_out[1].position = Vec2(0x1p49 + 0.5 + 2.0 - 0.625, 0x1p49);
    CHECK(named_overlap(vast, far_out) == first_and_second);
    pair[1].position = Vec2(25, 5);
    bool outside = false;
    try {
        ExactSimulation exact(params, pair);
    } catch (const std::invalid_argument&) {
        outside = true;
    }
    CHECK(outside);
}

void estimates_events() {
    // One disk crossing a box of span 8 at speed 4 per step: 0.5 wall hits a step.
    const World params{10.0, 1.0};
    std::vector<Particle> one(1);
    one[0].position = Vec2(5, 5);
    one[0].velocity = Vec2(4, 0);
    CHECK_NEAR(estimated_events_per_step(params, one), 0.5, 1e-15);
    one[0].velocity = Vec2::Zero();
    CHECK_EQ(estimated_events_per_step(params, one), 0.0);
    one[0].velocity = Vec2(1, 0);
    one[0].position = Vec2(1, 1);
    CHECK(std::isinf(estimated_events_per_step(World{2.0, 1.0}, one)));
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_exact_engine",
        {{"wall then pair", wall_then_pair},
         {"hand built examples", hand_built_examples},
         {"same events for every cell size", same_events_for_every_cell_size},
         {"agrees with stepped engine when events do not share a particle",
          agrees_with_stepped_engine_when_events_do_not_share_a_particle},
         {"conserves and stays inside", conserves_and_stays_inside},
         {"refuses overlaps and bad scenes", refuses_overlaps_and_bad_scenes},
         {"estimates events", estimates_events},
         {"counts events", counts_events},
         {"look ahead changes no event", look_ahead_changes_no_event},
         {"crowded starts refine the cells", crowded_starts_refine_the_cells},
         {"the state read late is the state read every step", state_read_late_is_the_state_read_every_step},
         {"both queues give the same events", both_queues_give_the_same_events}});
}
