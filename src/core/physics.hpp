#pragma once
// The pure physics of the step rules: time to a wall, time to contact, the
// wall bounce, the elastic exchange and the "stop at the wall" motion. Every
// engine calls these and nothing else, so engines cannot disagree on physics.

#include "core/box.hpp"
#include "core/double_double.hpp"
#include "particlesim/particle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace particlesim {

inline constexpr double never = std::numeric_limits<double>::infinity();

struct WallHit {
    double time = never;
    bool on_x = false;  // reaches x = r or x = L - r at `time`
    bool on_y = false;  // both: a corner hit
};

// Two doubles side by side (SSE2 on x86-64, NEON on AArch64), for two
// computations at once: each lane is the same IEEE arithmetic as a double.
using TwoDoubles = double __attribute__((vector_size(16)));
using TwoMasks = std::int64_t __attribute__((vector_size(16)));  // what comparing two lanes gives

// The time for each coordinate to reach the wall it moves towards (`never`
// without motion on it), in two lanes (x, y), with selects instead of
// branches: directions are random, so a branch on a sign is mispredicted
// half the time. Each lane is the same IEEE arithmetic as a scalar (same
// bits everywhere).
inline TwoDoubles times_to_walls(const TwoDoubles& where, const TwoDoubles& speed, const TwoDoubles& lower,
                                 const TwoDoubles& upper) {
    const TwoDoubles wall = speed < 0.0 ? lower : upper;
    // "+ 0.0" turns the -0.0 of a particle resting on the wall into +0.0.
    const TwoDoubles to_wall = (wall - where) / speed + 0.0;
    return speed != 0.0 ? to_wall : TwoDoubles{never, never};
}

// The earlier of the two wall times, and which it was.
inline WallHit time_to_wall(const Vec2& position, const Vec2& velocity, const Box& box) {
    const TwoDoubles times =
        times_to_walls(TwoDoubles{position.x(), position.y()}, TwoDoubles{velocity.x(), velocity.y()},
                       TwoDoubles{box.lower, box.lower}, TwoDoubles{box.upper, box.upper});
    const double t = std::min(times[0], times[1]);
    return {t, times[0] == t && t != never, times[1] == t && t != never};
}

// First contact time of a pair from relative position dp = p_j - p_i and
// relative velocity dv = v_j - v_i; `never` when they do not collide. A
// touching or overlapping pair collides at t = 0 when it approaches.
inline double contact_time(const Vec2& dp, const Vec2& dv, double contact_dist_sq) {
    const double a = dv.dot(dv);
    const double half_b = dp.dot(dv);
    const double c = dp.dot(dp) - contact_dist_sq;
    // (B^2 - 4AC) / 4 rewritten with Lagrange's identity as (2r)^2 A - (dp x dv)^2:
    // it avoids the cancellation of B^2 against 4AC for distant pairs.
    const double cross = dp.x() * dv.y() - dp.y() * dv.x();
    const double quarter_disc = contact_dist_sq * a - cross * cross;
    // A contact needs relative motion (A != 0) towards each other (B < 0), and
    // either a touching start (C <= 0) or a real crossing (disc > 0; not a
    // graze). Decided without branches: most pairs a search tests recede or
    // miss, in no pattern a branch predictor could learn.
    // "A == 0" of the rules is tested on dv itself: A can underflow to 0 for a
    // tiny nonzero dv, and then a touching pair would wrongly stay apart.
    // |dvx| + |dvy| is 0 only when dv is (a sum of magnitudes cannot cancel).
    const bool moving = std::fabs(dv.x()) + std::fabs(dv.y()) != 0.0;
    const bool approaching = moving & (half_b < 0.0);
    const bool touching = c <= 0.0;
    if (!(approaching & (touching | (quarter_disc > 0.0)))) return never;
    if (touching) return 0.0;
    return c / (std::sqrt(quarter_disc) - half_b);  // the smaller root, without cancellation
}

// The rare end of contact_times(), out of line so that the common path
// keeps its values in registers: the lanes that meet, one at a time. Not
// marked cold: GCC then calls libm's sqrt through the PLT instead of the
// instruction (5 % of a small exact run).
[[gnu::noinline]] inline TwoDoubles meeting_times(TwoMasks meets, TwoMasks touching, TwoDoubles c,
                                                  TwoDoubles quarter_disc, TwoDoubles half_b) {
    TwoDoubles times{never, never};
    for (int lane = 0; lane < 2; ++lane) {
        if (meets[lane] == 0) continue;
        times[lane] = touching[lane] != 0 ? 0.0 : c[lane] / (std::sqrt(quarter_disc[lane]) - half_b[lane]);
    }
    return times;
}

// contact_time() of two pairs at once, one in each lane, from the lanes of
// dp and dv: the same bits as two calls, with no branch on either pair. Most
// pairs an engine tests never meet; only a contact takes the square root.
// (contact_time() stays for one pair: a lane left idle costs more than it.)
inline TwoDoubles contact_times(const TwoDoubles& dpx, const TwoDoubles& dpy, const TwoDoubles& dvx,
                                const TwoDoubles& dvy, double contact_dist_sq) {
    const TwoDoubles a = dvx * dvx + dvy * dvy;
    const TwoDoubles half_b = dpx * dvx + dpy * dvy;
    const TwoDoubles c = (dpx * dpx + dpy * dpy) - contact_dist_sq;
    const TwoDoubles cross = dpx * dvy - dpy * dvx;
    const TwoDoubles quarter_disc = contact_dist_sq * a - cross * cross;
    // |dvx| + |dvy| != 0 exactly when either is nonzero.
    const TwoMasks moving = (dvx != 0.0) | (dvy != 0.0);
    const TwoMasks touching = c <= 0.0;
    const TwoMasks crossing = quarter_disc > 0.0;
    const TwoMasks approaching = half_b < 0.0;
    const TwoMasks meets = moving & approaching & (touching | crossing);
    if ((meets[0] | meets[1]) == 0) return TwoDoubles{never, never};
    return meeting_times(meets, touching, c, quarter_disc, half_b);
}

// Two disks overlap when their centres are closer than 2r by more than this
// fraction of (2r)^2: shallower overlaps are rounding at a contact, which the
// step rules and the exact engine both treat as touching.
inline constexpr double overlap_tolerance = 1e-6;

inline bool disks_overlap(const Vec2& dp, double contact_dist_sq) {
    return dp.dot(dp) < contact_dist_sq * (1.0 - overlap_tolerance);
}

// The image of `coordinate` a whole number of sides away that lies nearest
// `reference`, in a periodic box of side `side`.
inline double image_nearest(double coordinate, double reference, double side) {
    return coordinate - side * std::round((coordinate - reference) / side);
}

// A separation along one axis of a periodic box, to the nearest image.
inline double nearest_image(double separation, double side) { return image_nearest(separation, 0.0, side); }

// A coordinate of a periodic box of side `side` wrapped into [0, side): a
// hair below 0 that rounds up to `side` becomes 0.
inline double wrap_into_periodic_box(double coordinate, double side) {
    if (coordinate > 0.0 && coordinate < side)
        return coordinate;  // nearly always; the same value (0 and -0 go on: to +0)
    const double wrapped = coordinate - side * std::floor(coordinate / side);
    return wrapped < side ? std::max(wrapped, 0.0) : 0.0;
}

inline void clamp_into_box(Vec2& position, const Box& box) {
    position.x() = std::clamp(position.x(), box.lower, box.upper);
    position.y() = std::clamp(position.y(), box.lower, box.upper);
}

// Puts every coordinate named by `hit` exactly on its wall (the side the
// velocity points to) and keeps the other inside the box despite rounding.
inline void place_on_wall(Vec2& position, const Vec2& velocity, const WallHit& hit, const Box& box) {
    clamp_into_box(position, box);
    if (hit.on_x) position.x() = velocity.x() < 0.0 ? box.lower : box.upper;
    if (hit.on_y) position.y() = velocity.y() < 0.0 ? box.lower : box.upper;
}

// Wall collision at `time`: move there, sit exactly on the wall, reflect.
inline void bounce_off_wall(Particle& particle, const WallHit& hit, const Box& box) {
    particle.position += particle.velocity * hit.time;
    place_on_wall(particle.position, particle.velocity, hit, box);
    if (hit.on_x) particle.velocity.x() = -particle.velocity.x();
    if (hit.on_y) particle.velocity.y() = -particle.velocity.y();
    ++particle.wall_collisions;
}

// Elastic collision of equal masses at contact positions pi, pj: exchange the
// velocity components along the line of centres, keep the tangential ones.
// ((vj - vi).n) n is computed as ((vj - vi).d / d.d) d, with no unit normal
// and in double-double precision, so that the only rounding left is the final
// one to double, which is unbiased: energy drifts as a random walk instead of
// steadily, as it does with a unit normal or double intermediates
// (docs/accuracy.md, "Stability"). Double-double rounds the same on every IEEE
// machine, so the bytes do not depend on the platform.
//
// On components, for one collision (Real = double) or for several at once,
// one in each lane of a vector: every lane is the same arithmetic, so the
// same bits. The exchange is one long chain of dependent operations; two
// collisions side by side take little longer than one.
template <typename Real>
struct ContactPair {
    Real pix, piy, pjx, pjy;  // the positions at contact
    Real vix, viy, vjx, vjy;  // the velocities, exchanged in place
};

template <typename Real>
inline void exchange_normal_components(ContactPair<Real>& c) {
    const DoubleDoubleOf<Real> dx = two_sum(c.pjx, -c.pix);
    const DoubleDoubleOf<Real> dy = two_sum(c.pjy, -c.piy);
    const DoubleDoubleOf<Real> dist_sq = dx * dx + dy * dy;
    const DoubleDoubleOf<Real> dvx = two_sum(c.vjx, -c.vix);
    const DoubleDoubleOf<Real> dvy = two_sum(c.vjy, -c.viy);
    const DoubleDoubleOf<Real> along = (dvx * dx + dvy * dy) / dist_sq;
    const DoubleDoubleOf<Real> ex = along * dx;
    const DoubleDoubleOf<Real> ey = along * dy;
    // Never at distance 0 for valid radii; no lane takes a quotient by zero.
    const auto apart = dist_sq.hi > 0.0;
    const Real vix = rounded_sum(c.vix, ex);
    const Real viy = rounded_sum(c.viy, ey);
    const Real vjx = rounded_sum(c.vjx, -ex);
    const Real vjy = rounded_sum(c.vjy, -ey);
    c.vix = apart ? vix : c.vix;
    c.viy = apart ? viy : c.viy;
    c.vjx = apart ? vjx : c.vjx;
    c.vjy = apart ? vjy : c.vjy;
}

inline void exchange_normal_velocities(const Vec2& pi, const Vec2& pj, Vec2& vi, Vec2& vj) {
    ContactPair<double> c{pi.x(), pi.y(), pj.x(), pj.y(), vi.x(), vi.y(), vj.x(), vj.y()};
    exchange_normal_components(c);
    vi = Vec2(c.vix, c.viy);
    vj = Vec2(c.vjx, c.vjy);
}

// The rest of a step after a collision: move for `remaining`, but stop on a
// wall reached on the way (its collision happens at t = 0 of the next step).
inline void move_stopping_at_wall(Particle& particle, double remaining, const Box& box) {
    const WallHit hit = time_to_wall(particle.position, particle.velocity, box);
    if (hit.time <= remaining) {
        particle.position += particle.velocity * hit.time;
        place_on_wall(particle.position, particle.velocity, hit, box);
    } else {
        particle.position += particle.velocity * remaining;
        clamp_into_box(particle.position, box);
    }
}

// Free flight for a particle that has no wall within `duration`.
inline void move_freely(Particle& particle, double duration, const Box& box) {
    particle.position += particle.velocity * duration;
    clamp_into_box(particle.position, box);
}

inline double kinetic_energy(const Particle& particle) { return 0.5 * particle.velocity.squaredNorm(); }

}  // namespace particlesim
