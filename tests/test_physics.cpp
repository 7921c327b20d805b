// The pure physics functions against values worked out by hand.

#include "check.hpp"
#include "wall_motions.hpp"

#include "core/motion_lanes.hpp"
#include "core/physics.hpp"
#include "core/random.hpp"

#include <bit>
#include <cmath>

using namespace particlesim;

namespace {

const Box box = Box::of(World{20.0, 1.0});  // centres in [1, 19]

void wall_times() {
    // x = 10 moving +2: reaches 19 at t = 4.5; y = 5 moving -1: reaches 1 at t = 4.
    const WallHit hit = time_to_wall(Vec2(10, 5), Vec2(2, -1), box);
    CHECK_EQ(hit.time, 4.0);
    CHECK(!hit.on_x);
    CHECK(hit.on_y);
    // No motion: never.
    CHECK_EQ(time_to_wall(Vec2(10, 10), Vec2(0, 0), box).time, never);
    // Corner: both axes at t = 2.
    const WallHit corner = time_to_wall(Vec2(17, 17), Vec2(1, 1), box);
    CHECK_EQ(corner.time, 2.0);
    CHECK(corner.on_x && corner.on_y);
    // Resting on the wall and moving into it: t = +0 (not -0).
    const double t = time_to_wall(Vec2(1, 10), Vec2(-3, 0), box).time;
    CHECK_EQ(t, 0.0);
    CHECK(!std::signbit(t));
}

void hand_worked_contact_times() {
    const double d2 = box.contact_dist_sq;  // 4
    // Head-on: gap 8 - 2 = 6 closing at 2 per step: t = 3.
    CHECK_EQ(contact_time(Vec2(8, 0), Vec2(-2, 0), d2), 3.0);
    // Overlapping (distance 1) and approaching: t = 0.
    CHECK_EQ(contact_time(Vec2(1, 0), Vec2(-1, 0), d2), 0.0);
    // Touching exactly (C == 0) and approaching: t = 0.
    CHECK_EQ(contact_time(Vec2(2, 0), Vec2(-1, 0), d2), 0.0);
    // Overlapping and receding: none.
    CHECK_EQ(contact_time(Vec2(1, 0), Vec2(1, 0), d2), never);
    // Overlapping, moving sideways (B == 0): none.
    CHECK_EQ(contact_time(Vec2(1, 0), Vec2(0, 1), d2), never);
    // Graze: passing at exactly 2r (offset 2, moving along x): discriminant 0, none.
    CHECK_EQ(contact_time(Vec2(10, 2), Vec2(-1, 0), d2), never);
    // Just inside the graze: a collision, later than head-on.
    const double near_graze = contact_time(Vec2(10, 1.999), Vec2(-1, 0), d2);
    CHECK(near_graze > 8.0 && near_graze < 10.0);
    // Miss: offset 3.
    CHECK_EQ(contact_time(Vec2(10, 3), Vec2(-1, 0), d2), never);
    // No relative motion, even when overlapping: none.
    CHECK_EQ(contact_time(Vec2(1, 0), Vec2(0, 0), d2), never);
    CHECK_EQ(contact_time(Vec2(5, 0), Vec2(0, 0), d2), never);
    // Coincident centres: B == 0, so none, and no normal is ever needed.
    CHECK_EQ(contact_time(Vec2(0, 0), Vec2(1, 1), d2), never);
    // Glancing: offset 1.5, contact when dx = sqrt(4 - 2.25) = sqrt(1.75).
    CHECK_NEAR(contact_time(Vec2(6, 1.5), Vec2(-1, 0), d2), 6.0 - std::sqrt(1.75), 1e-14);
    // Receding from far away: none.
    CHECK_EQ(contact_time(Vec2(8, 0), Vec2(1, 0), d2), never);
}

// The exact engine tests a pair in the order it meets it (its own particle
// first) and relies on getting the same bits either way round: negating dp
// and dv must change nothing.
void contact_time_is_symmetric_to_the_bit() {
    SplitMix64 rng(77);
    int asymmetric = 0;
    int contacts = 0;
    for (int k = 0; k < 200000; ++k) {
        // Magnitudes from 1e-3 to 1e3 times the contact distance, any sign.
        const auto value = [&] { return (rng.uniform() - 0.5) * std::pow(10.0, 6.0 * rng.uniform() - 3.0); };
        const Vec2 dp(value(), value());
        const Vec2 dv(value(), value());
        const double d2 = 4.0 * std::pow(10.0, 2.0 * rng.uniform() - 1.0);
        const double forward = contact_time(dp, dv, d2);
        const double backward = contact_time(-dp, -dv, d2);
        asymmetric += std::bit_cast<std::uint64_t>(forward) == std::bit_cast<std::uint64_t>(backward) ? 0 : 1;
        contacts += forward != never ? 1 : 0;
    }
    CHECK_EQ(asymmetric, 0);
    CHECK(contacts > 10000);  // the sample reaches the arithmetic past the early "never"
}

// Two pair tests side by side in the lanes of a vector give the bits each
// gives alone: distances and speeds from 2^-60 to 2^60 of the contact
// distance, touching and overlapping starts, grazes, and no relative motion
// on one or both axes.
void contact_times_in_lanes_are_contact_time_alone() {
    SplitMix64 rng(79);
    const auto same = [](double a, double b) {
        return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
    };
    const auto random_motion = [&](double d2) {
        const auto value = [&] {
            return (rng.uniform() - 0.5) * std::ldexp(1.0, static_cast<int>(120.0 * rng.uniform()) - 60);
        };
        Vec2 dp(value(), value());
        Vec2 dv(value(), value());
        const double kind = rng.uniform();
        if (kind < 0.1) dp = random_direction(rng) * std::sqrt(d2) * (1.0 - 0.5 * rng.uniform());  // touching
        if (kind > 0.9) dp = Vec2(dv.y(), -dv.x()).normalized() * std::sqrt(d2) - dv * 5.0;        // a graze
        if (rng.uniform() < 0.05) dv.x() = 0.0;
        if (rng.uniform() < 0.05) dv.y() = 0.0;
        return std::pair{dp, dv};
    };
    int differing = 0;
    int contacts = 0;
    for (int k = 0; k < 200000; ++k) {
        const double d2 = 4.0 * std::ldexp(1.0, static_cast<int>(40.0 * rng.uniform()) - 20);
        const auto [dp0, dv0] = random_motion(d2);
        const auto [dp1, dv1] = random_motion(d2);
        const TwoDoubles together = contact_times(TwoDoubles{dp0.x(), dp1.x()}, TwoDoubles{dp0.y(), dp1.y()},
                                                  TwoDoubles{dv0.x(), dv1.x()}, TwoDoubles{dv0.y(), dv1.y()}, d2);
        const double alone[2] = {contact_time(dp0, dv0, d2), contact_time(dp1, dv1, d2)};
        for (int lane = 0; lane < 2; ++lane) {
            differing += same(alone[lane], together[lane]) ? 0 : 1;
            contacts += alone[lane] != never ? 1 : 0;
        }
    }
    CHECK_EQ(differing, 0);
    CHECK(contacts > 40000);  // both outcomes, and the square root, are well sampled
}

void exchange_conserves_energy_and_momentum() {
    // Head-on, equal speeds: velocities swap.
    Vec2 va(1, 0), vb(-1, 0);
    exchange_normal_velocities(Vec2(0, 0), Vec2(2, 0), va, vb);
    CHECK_EQ(va.x(), -1.0);
    CHECK_EQ(vb.x(), 1.0);
    CHECK_EQ(va.y(), 0.0);
    // Glancing (normal (sqrt(1.75), 1.5) / 2): hand values 0.45 / 0.35 along x.
    Vec2 v0(0.8, 0), v1(0, 0);
    exchange_normal_velocities(Vec2(0, 0), Vec2(std::sqrt(1.75), 1.5), v0, v1);
    CHECK_NEAR(v0.x(), 0.45, 1e-15);
    CHECK_NEAR(v1.x(), 0.35, 1e-15);
    CHECK_NEAR(v0.y(), -v1.y(), 1e-15);
    // Arbitrary: momentum and energy conserved to rounding.
    Vec2 a(3.7, -1.2), b(-0.4, 2.9);
    const Vec2 momentum = a + b;
    const double energy = a.squaredNorm() + b.squaredNorm();
    exchange_normal_velocities(Vec2(1.3, 2.2), Vec2(2.1, 3.9), a, b);
    CHECK_NEAR((a + b - momentum).norm(), 0.0, 1e-14);
    CHECK_NEAR(a.squaredNorm() + b.squaredNorm(), energy, 1e-13);
    // Coincident centres leave velocities alone instead of dividing by zero.
    Vec2 c(1, 0), d(0, 1);
    exchange_normal_velocities(Vec2(5, 5), Vec2(5, 5), c, d);
    CHECK(c.allFinite() && d.allFinite());
}

// Two collisions side by side in the lanes of a vector give the bits each
// gives alone: contacts at every scale of the accepted range (a length of
// 2^k times the radius, k from -190 to 190), tiny and zero relative speeds,
// and coincident centres.
void exchange_in_lanes_is_exchange_alone() {
    SplitMix64 rng(78);
    const auto same = [](double a, double b) {
        return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
    };
    const auto random_contact = [&] {
        const double scale = std::ldexp(1.0, static_cast<int>(380.0 * rng.uniform()) - 190);
        const double speed_scale = rng.uniform() < 0.1 ? std::ldexp(scale, -200) : scale;
        const auto value = [&](double unit) { return (rng.uniform() - 0.5) * unit; };
        const Vec2 normal = random_direction(rng) * (2.0 * scale);
        ContactPair<double> c{value(scale),       value(scale),      0.0, 0.0, value(speed_scale), value(speed_scale),
                              value(speed_scale), value(speed_scale)};
        c.pjx = c.pix + normal.x();
        c.pjy = c.piy + normal.y();
        if (rng.uniform() < 0.02) c.vjx = c.vix, c.vjy = c.viy;  // no relative motion
        if (rng.uniform() < 0.01) c.pjx = c.pix, c.pjy = c.piy;  // coincident centres
        return c;
    };
    int differing = 0;
    for (int k = 0; k < 100000; ++k) {
        ContactPair<double> alone[2] = {random_contact(), random_contact()};
        const auto lanes = [&](double ContactPair<double>::*member) {
            return TwoDoubles{alone[0].*member, alone[1].*member};
        };
        ContactPair<TwoDoubles> together{lanes(&ContactPair<double>::pix), lanes(&ContactPair<double>::piy),
                                         lanes(&ContactPair<double>::pjx), lanes(&ContactPair<double>::pjy),
                                         lanes(&ContactPair<double>::vix), lanes(&ContactPair<double>::viy),
                                         lanes(&ContactPair<double>::vjx), lanes(&ContactPair<double>::vjy)};
        exchange_normal_components(together);
        for (int lane = 0; lane < 2; ++lane) {
            ContactPair<double>& c = alone[lane];
            exchange_normal_components(c);
            const bool equal = same(c.vix, together.vix[lane]) && same(c.viy, together.viy[lane]) &&
                               same(c.vjx, together.vjx[lane]) && same(c.vjy, together.vjy[lane]);
            differing += equal ? 0 : 1;
        }
    }
    CHECK_EQ(differing, 0);
}

void bounce_and_stop_at_wall() {
    // Bounce at t = 0.5 on x = 19: x is set exactly, vx negated, wc counted.
    Particle p;
    p.position = Vec2(18, 10);
    p.velocity = Vec2(2, 0.5);
    bounce_off_wall(p, time_to_wall(p.position, p.velocity, box), box);
    CHECK_EQ(p.position.x(), 19.0);
    CHECK_EQ(p.position.y(), 10.25);
    CHECK_EQ(p.velocity.x(), -2.0);
    CHECK_EQ(p.wall_collisions, 1U);
    // After a collision, the rest of the step stops at the wall it reaches.
    Particle q;
    q.position = Vec2(17, 10);
    q.velocity = Vec2(4, 0);
    move_stopping_at_wall(q, 1.0, box);
    CHECK_EQ(q.position.x(), 19.0);
    CHECK_EQ(q.velocity.x(), 4.0);  // unchanged: the bounce comes next step
    // Free flight stays inside even when rounding would push it out.
    Particle r;
    r.position = Vec2(19.0 - 1e-16, 10);
    r.velocity = Vec2(1e-15, 0);
    move_freely(r, 1.0, box);
    CHECK(r.position.x() <= box.upper);
}

// The two lanes' wall time, free flight, bounce and stop at a wall give the
// scalar functions' bits: on random motions, exact corners, particles
// resting on a wall, at rest, and a second wall reached exactly at the end
// of the step.
void motion_lanes_are_the_scalar_motion() {
    SplitMix64 rng(23);
    const auto same = [](const Vec2& a, const Vec2& b) {
        return std::bit_cast<std::uint64_t>(a.x()) == std::bit_cast<std::uint64_t>(b.x()) &&
               std::bit_cast<std::uint64_t>(a.y()) == std::bit_cast<std::uint64_t>(b.y());
    };
    const auto coordinate = [&] { return test_scenes::wall_coordinate(rng, box); };
    const auto speed = [&] { return test_scenes::wall_speed(rng, 40.0); };
    int differing = 0;
    int corners = 0;
    int stopped = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        Particle p;
        p.position = Vec2(coordinate(), coordinate());
        p.velocity = Vec2(speed(), speed());
        if (trial % 50 == 0) {  // an exact corner: both walls at t = 1
            p.position = Vec2(17, 3);
            p.velocity = Vec2(2, -2);
        }
        const WallHit hit = time_to_wall(p.position, p.velocity, box);
        corners += hit.on_x && hit.on_y ? 1 : 0;
        Particle scalar = p;
        MotionLanes lanes(p, box);
        CHECK(std::bit_cast<std::uint64_t>(lanes.wall_time()) == std::bit_cast<std::uint64_t>(hit.time));
        // A free flight, up to past the walls (clamped), and for +0.0.
        Particle flown = p;
        MotionLanes flying(p, box);
        const double flight = trial % 3 == 0 ? 0.0 : 2.0 * rng.uniform();
        move_freely(flown, flight, box);
        flying.fly(flight);
        CHECK(same(flown.position, flying.position()) && same(flown.velocity, flying.velocity()));
        if (hit.time != never) {
            bounce_off_wall(scalar, hit, box);
            lanes.bounce();
        }
        // Half the time exactly as long as the next wall is away.
        const double next = time_to_wall(scalar.position, scalar.velocity, box).time;
        const double remaining = trial % 2 == 0 && next != never ? next : 2.0 * rng.uniform();
        stopped += next <= remaining ? 1 : 0;
        move_stopping_at_wall(scalar, remaining, box);
        lanes.move_stopping_at_wall(remaining);
        if (!same(scalar.position, lanes.position()) || !same(scalar.velocity, lanes.velocity())) {
            ++differing;
            const check::Context context("trial ", trial);
            CHECK(same(scalar.position, lanes.position()));
        }
    }
    CHECK_EQ(differing, 0);
    CHECK(corners > 4000);
    CHECK(stopped > 100000);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(argc, argv, "test_physics",
                      {{"wall times", wall_times},
                       {"contact times", hand_worked_contact_times},
                       {"contact time is symmetric to the bit", contact_time_is_symmetric_to_the_bit},
                       {"contact times in lanes are contact time alone", contact_times_in_lanes_are_contact_time_alone},
                       {"exchange conserves energy and momentum", exchange_conserves_energy_and_momentum},
                       {"exchange in lanes is the exchange alone", exchange_in_lanes_is_exchange_alone},
                       {"bounce and stop at wall", bounce_and_stop_at_wall},
                       {"motion lanes are the scalar motion", motion_lanes_are_the_scalar_motion}});
}
