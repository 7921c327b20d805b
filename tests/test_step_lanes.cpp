// The stepped engine's loops in AVX-512 lanes give what their one-at-a-time
// forms give, bit for bit: the free flight with its wall times and the wall
// bounces (MotionLanes), the listing of the collided particles, and the
// wall candidates' records; on random particles at rest, on walls and flying
// past them, blocks of every length and start, and lists that run out of
// room. On a processor without AVX-512 the lanes move nothing, which the
// cases check instead (and say so).

#include "check.hpp"
#include "wall_motions.hpp"

#include "core/avx512_lanes.hpp"
#include "core/box.hpp"
#include "core/collision.hpp"
#include "core/motion_lanes.hpp"
#include "core/physics.hpp"
#include "core/random.hpp"
#include "stepped/collided_lists.hpp"
#include "stepped/free_flight_lanes.hpp"
#include "stepped/wall_bounce_lanes.hpp"
#include "stepped/wall_candidate_lanes.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

using namespace particlesim;

namespace {

// Fewer under AddressSanitizer (check.hpp).
constexpr int trials = check::sanitized ? 200 : 2000;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

const Box box{40.0, 1.0, 39.0, 4.0};

// Particles on the walls, at rest, crossing the box in a step and slower,
// and reaching a wall exactly at the end of a step of 1 (and then of 2);
// partners free, resolved against a wall, or a particle's index.
struct Flock {
    std::vector<Particle> particles;
    std::vector<std::uint32_t> partner;
};
Flock random_flock(SplitMix64& rng, std::size_t count) {
    const auto coordinate = [&] { return test_scenes::wall_coordinate(rng, box); };
    const auto speed = [&] { return test_scenes::wall_speed(rng, 80.0); };
    Flock flock;
    for (std::size_t i = 0; i < count; ++i) {
        Particle p;
        p.position = Vec2(coordinate(), coordinate());
        p.velocity = Vec2(speed(), speed());
        if (rng.next() % 8 == 0) {  // after a free flight of 1, at the wall in exactly 1 more
            p.position.x() = 35.0;
            p.velocity.x() = 2.0;
        }
        p.particle_collisions = rng.next();
        p.wall_collisions = rng.next();
        flock.particles.push_back(p);
        const std::uint64_t kind = rng.next() % 4;
        flock.partner.push_back(kind < 2    ? no_collision
                                : kind == 2 ? wall_collision
                                            : static_cast<std::uint32_t>(rng.next() % count));
    }
    return flock;
}

// A case's end: with the lanes, that more than `at_least` trials reached
// them (else the case proved little); without, a line saying what was
// checked instead.
void check_lanes_reached(const char* what, int reached, int at_least) {
    if (!avx512_lanes_available()) {
        std::printf("test_step_lanes: this processor has no AVX-512: %s checked to move nothing\n", what);
        return;
    }
    const check::Context context(what);
    CHECK(reached > at_least);
}

// fly_four_at_a_time() against MotionLanes particle by particle: the same
// positions, untouched velocities and counts, every partner freed, the
// same wall times and wall candidates.
void free_flight_is_motion_lanes() {
    SplitMix64 rng(41);
    int blocks = 0;
    for (int trial = 0; trial < trials; ++trial) {
        const std::size_t count = 1 + rng.next() % 70;
        Flock flock = random_flock(rng, count);
        const Flock before = flock;
        const auto first = static_cast<std::int64_t>(rng.next() % count);
        const auto last = static_cast<std::int64_t>(count);
        const double step = trial % 5 == 0 ? 1.0 : 2.0 * rng.uniform();
        std::vector<double> wall_time(count, -1.0);
        std::uint32_t candidates = 7;
        const std::int64_t end = fly_four_at_a_time(flock.particles.data(), flock.partner.data(), wall_time.data(), box,
                                                    step, first, last, candidates);
        const check::Context context("trial ", trial);
        if (!avx512_lanes_available()) {
            CHECK_EQ(end, first);
            continue;
        }
        CHECK(end >= first && end <= last && (end - first) % 4 == 0 && last - end < 4);
        std::uint32_t expected_candidates = 7;
        for (std::int64_t i = 0; i < last; ++i) {
            const Particle& was = before.particles[i];
            const Particle& now = flock.particles[i];
            if (i < first || i >= end) {  // not the lanes' to touch
                CHECK(same_bits(now.position.x(), was.position.x()) && same_bits(now.position.y(), was.position.y()));
                CHECK_EQ(flock.partner[i], before.partner[i]);
                CHECK(wall_time[i] == -1.0);
                continue;
            }
            MotionLanes motion(was, box);
            motion.fly(before.partner[i] == no_collision ? step : 0.0);
            const double time = motion.wall_time();
            expected_candidates += time <= step ? 1U : 0U;
            CHECK(same_bits(now.position.x(), motion.position().x()) &&
                  same_bits(now.position.y(), motion.position().y()));
            CHECK(same_bits(now.velocity.x(), was.velocity.x()) && same_bits(now.velocity.y(), was.velocity.y()));
            CHECK(now.particle_collisions == was.particle_collisions && now.wall_collisions == was.wall_collisions);
            CHECK_EQ(flock.partner[i], no_collision);
            CHECK(same_bits(wall_time[i], time));
        }
        CHECK_EQ(candidates, expected_candidates);
        blocks += end > first ? 1 : 0;
    }
    check_lanes_reached("the free flight", blocks, trials / 2);
}

// list_collided() against the scalar rule: pairs at their lower index,
// walls, in increasing order; nothing written past the lists' spill.
void collided_lists_are_the_rule() {
    SplitMix64 rng(43);
    for (int trial = 0; trial < trials; ++trial) {
        const std::size_t count = rng.next() % 100 + (trial % 10 == 0 ? 1024 : 0);
        const Flock flock = random_flock(rng, count == 0 ? 1 : count);
        const auto first = static_cast<std::int64_t>(count == 0 ? 0 : rng.next() % count);
        const auto last = static_cast<std::int64_t>(count);
        const std::size_t room = static_cast<std::size_t>(last - first) + collided_lists_spill;
        constexpr std::uint32_t guard = 0xabcdef01U;
        std::vector<std::uint32_t> pair_at(room + 4, guard);
        std::vector<std::uint32_t> wall_at(room + 4, guard);
        const CollidedCounts listed = list_collided(flock.partner.data(), first, last, pair_at.data(), wall_at.data());
        std::vector<std::uint32_t> pairs;
        std::vector<std::uint32_t> walls;
        for (std::int64_t i = first; i < last; ++i) {
            const std::uint32_t other = flock.partner[i];
            if (other == wall_collision) walls.push_back(static_cast<std::uint32_t>(i));
            if (other < wall_collision && static_cast<std::uint32_t>(i) < other)
                pairs.push_back(static_cast<std::uint32_t>(i));
        }
        const check::Context context("trial ", trial);
        CHECK(std::vector<std::uint32_t>(pair_at.begin(), pair_at.begin() + listed.pairs) == pairs);
        CHECK(std::vector<std::uint32_t>(wall_at.begin(), wall_at.begin() + listed.walls) == walls);
        for (std::size_t k = room; k < room + 4; ++k) CHECK(pair_at[k] == guard && wall_at[k] == guard);
    }
}

// write_wall_candidates_in_lanes() and the one-at-a-time rest: the records
// of the particles at or before the step's end, in index order, none past
// the room given (also when it runs out).
void wall_candidates_are_the_rule() {
    SplitMix64 rng(47);
    int in_lanes = 0;
    for (int trial = 0; trial < trials; ++trial) {
        const std::size_t count = 1 + rng.next() % 90;
        std::vector<double> wall_time(count);
        for (double& time : wall_time) {
            const std::uint64_t kind = rng.next() % 6;
            time = kind == 0 ? never : kind == 1 ? 1.0 : 4.0 * rng.uniform();
        }
        const auto first = static_cast<std::int64_t>(rng.next() % count);
        const auto last = static_cast<std::int64_t>(count);
        const double duration = 1.0;
        std::vector<Collision> expected;
        for (std::int64_t i = first; i < last; ++i) {
            if (wall_time[i] <= duration)
                expected.push_back(Collision::wall(wall_time[i], static_cast<std::uint32_t>(i)));
        }
        // Room for all, or a few short of it.
        const std::size_t room = trial % 3 == 0 && !expected.empty() ? rng.next() % expected.size() : expected.size();
        const Collision guard = Collision::pair(-5.0, 7, 9);
        std::vector<Collision> out(room + 3, guard);
        const WallCandidatesWritten lanes =
            write_wall_candidates_in_lanes(wall_time.data(), duration, first, last, out.data(), room);
        const check::Context context("trial ", trial);
        CHECK(lanes.written <= room && lanes.next >= first && lanes.next <= last);
        // The rest as the stepped engine writes it.
        std::size_t at = lanes.written;
        for (std::int64_t i = lanes.next; i < last && at < room; ++i) {
            out[at] = Collision::wall(wall_time[i], static_cast<std::uint32_t>(i));
            at += wall_time[i] <= duration ? 1 : 0;
        }
        for (std::size_t k = 0; k < room; ++k) CHECK(out[k] == expected[k] && same_bits(out[k].time, expected[k].time));
        for (std::size_t k = room; k < out.size(); ++k) CHECK(out[k] == guard);
        in_lanes += lanes.written > 0 ? 1 : 0;
        if (!avx512_lanes_available()) CHECK(lanes.next == first && lanes.written == 0);
    }
    check_lanes_reached("the wall candidates", in_lanes, trials / 4);
}

// resolve_walls_four_at_a_time() against MotionLanes particle by particle
// (resolve_wall()): bounced at the first wall, moved on for the rest of the
// step stopping at the next, the wall collision counted; the other
// particles untouched.
void wall_bounces_are_motion_lanes() {
    SplitMix64 rng(53);
    int resolved_in_lanes = 0;
    for (int trial = 0; trial < trials; ++trial) {
        const std::size_t count = 1 + rng.next() % 60;
        Flock flock = random_flock(rng, count);
        const double duration = trial % 5 == 0 ? 1.0 : 3.0 * rng.uniform();
        std::vector<double> collision_time(count, 0.0);
        std::vector<std::uint32_t> wall_at;
        for (std::uint32_t i = 0; i < count; ++i) {
            const WallHit hit = time_to_wall(flock.particles[i].position, flock.particles[i].velocity, box);
            collision_time[i] = hit.time;
            if (hit.time <= duration && rng.next() % 4 != 0) wall_at.push_back(i);
        }
        // In no order: the resolution lists them by index, the lanes must not care.
        for (std::size_t k = wall_at.size(); k > 1; --k) std::swap(wall_at[k - 1], wall_at[rng.next() % k]);
        const std::vector<Particle> before = flock.particles;
        const std::size_t resolved = resolve_walls_four_at_a_time(flock.particles.data(), wall_at.data(),
                                                                  wall_at.size(), collision_time.data(), box, duration);
        const check::Context context("trial ", trial);
        if (!avx512_lanes_available()) {
            CHECK_EQ(resolved, std::size_t{0});
            continue;
        }
        CHECK_EQ(resolved, wall_at.size() - wall_at.size() % 4);
        std::vector<Particle> expected = before;
        for (std::size_t k = 0; k < resolved; ++k) {
            Particle& p = expected[wall_at[k]];
            MotionLanes motion(p, box);
            motion.bounce();
            motion.move_stopping_at_wall(duration - collision_time[wall_at[k]]);
            p.position = motion.position();
            p.velocity = motion.velocity();
            ++p.wall_collisions;
        }
        for (std::size_t i = 0; i < count; ++i) {
            const Particle& got = flock.particles[i];
            const Particle& want = expected[i];
            CHECK(same_bits(got.position.x(), want.position.x()) && same_bits(got.position.y(), want.position.y()));
            CHECK(same_bits(got.velocity.x(), want.velocity.x()) && same_bits(got.velocity.y(), want.velocity.y()));
            CHECK(got.particle_collisions == want.particle_collisions && got.wall_collisions == want.wall_collisions);
        }
        resolved_in_lanes += resolved > 0 ? 1 : 0;
    }
    check_lanes_reached("the wall bounces", resolved_in_lanes, trials / 2);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_step_lanes",
                      {{"free flight is motion lanes", free_flight_is_motion_lanes},
                       {"collided lists are the rule", collided_lists_are_the_rule},
                       {"wall candidates are the rule", wall_candidates_are_the_rule},
                       {"wall bounces are motion lanes", wall_bounces_are_motion_lanes}});
}
