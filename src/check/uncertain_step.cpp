#include "check/uncertain_step.hpp"

#include "check/close_pairs.hpp"
#include "core/assert.hpp"
#include "core/physics.hpp"
#include "parallel/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <string>
#include <tuple>

namespace particlesim {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

Uncertain not_negative(const Uncertain& time) { return {std::max(time.lo, 0.0), std::max(time.hi, 0.0)}; }

// a <= b, decided or not.
Tri at_most(const Uncertain& a, const Uncertain& b) {
    if (a.hi <= b.lo) return Tri::yes;
    if (a.lo > b.hi) return Tri::no;
    return Tri::maybe;
}

// (B^2 - 4AC) / 4 = half_b^2 - A C computed in double: exact when every
// product and the difference are; otherwise off by about a unit in the last
// place of half_b^2.
Uncertain textbook_cancellation(const Uncertain& quarter_disc, const Uncertain& half_b, const Uncertain& a,
                                const Uncertain& c) {
    if (quarter_disc.is_exact() && half_b.is_exact() && a.is_exact() && c.is_exact()) {
        const DoubleDouble b_sq = two_product(half_b.lo, half_b.lo);
        const DoubleDouble ac = two_product(a.lo, c.lo);
        if (b_sq.lo == 0.0 && ac.lo == 0.0 && two_sum(b_sq.hi, -ac.hi).lo == 0.0) return quarter_disc;
    }
    const double scale = std::max(half_b.magnitude() * half_b.magnitude(), a.magnitude() * c.magnitude());
    return Uncertain::widened(quarter_disc.lo, quarter_disc.hi, scale);
}

struct AxisWall {
    Uncertain time = Uncertain::exact(infinity);  // to the first wall it may reach
    // The earliest it may reach each wall (infinity: it does not move towards it).
    double lower_from = infinity;
    double upper_from = infinity;
};

// rules.md "Wall candidate" on one axis.
AxisWall axis_wall(const Uncertain& position, const Uncertain& velocity, const Box& box) {
    if (velocity.lo > 0.0) {
        const Uncertain time = not_negative((Uncertain::exact(box.upper) - position) / velocity);
        return {time, infinity, time.lo};
    }
    if (velocity.hi < 0.0) {
        const Uncertain time = not_negative((Uncertain::exact(box.lower) - position) / velocity);
        return {time, time.lo, infinity};
    }
    if (velocity.lo == 0.0 && velocity.hi == 0.0) return {};
    // Its bounds straddle 0: it may creep to the wall on either side they
    // point to, no sooner than its distance over the fastest speed allowed.
    // (Bounds merged from several fates may allow real speeds both ways: then
    // either wall may be the one reached.)
    const auto no_sooner_than = [](double distance, double speed) {
        return std::max(0.0, distance / speed) * (1.0 - 0x1p-40);
    };
    AxisWall wall;
    if (velocity.lo < 0.0) wall.lower_from = no_sooner_than(position.lo - box.lower, -velocity.lo);
    if (velocity.hi > 0.0) wall.upper_from = no_sooner_than(box.upper - position.hi, velocity.hi);
    wall.time = Uncertain{std::min(wall.lower_from, wall.upper_from), infinity};
    return wall;
}

// Where an axis meets its wall within `limit`: the wall it moves to, or
// either one where both may be reached by then.
Uncertain wall_position(const AxisWall& axis, const Uncertain& limit, const Box& box) {
    const bool lower = axis.lower_from <= limit.hi;
    const bool upper = axis.upper_from <= limit.hi;
    if (lower && upper) return {box.lower, box.upper};
    if (lower || upper) return Uncertain::exact(lower ? box.lower : box.upper);
    return Uncertain::exact(axis.lower_from <= axis.upper_from ? box.lower : box.upper);  // not hit by then
}

struct WallReach {
    Uncertain time;
    Tri on_x = Tri::no;
    Tri on_y = Tri::no;
    Uncertain wall_x, wall_y;  // where the axes hit
};

// The first wall the particle may reach within `limit`, as far as decided.
// An axis whose own wall lies beyond the limit is not the one hit (a disk
// creeping along one wall, its time to it open-ended, does not jump to the
// other).
WallReach wall_reach(const UncertainParticle& q, const Box& box, const Uncertain& limit) {
    const AxisWall x = axis_wall(q.x, q.vx, box);
    const AxisWall y = axis_wall(q.y, q.vy, box);
    WallReach reach{min_of(x.time, y.time), Tri::maybe, Tri::maybe, wall_position(x, limit, box),
                    wall_position(y, limit, box)};
    if (x.time.hi < y.time.lo) {
        reach.on_x = Tri::yes;
        reach.on_y = Tri::no;
    } else if (y.time.hi < x.time.lo) {
        reach.on_x = Tri::no;
        reach.on_y = Tri::yes;
    } else if (x.time.is_exact() && y.time.is_exact() && x.time.lo == y.time.lo) {
        reach.on_x = reach.on_y = Tri::yes;  // a corner, exactly
    }
    if (!(x.time.lo <= limit.hi)) reach.on_x = Tri::no;  // also never (infinity)
    if (!(y.time.lo <= limit.hi)) reach.on_y = Tri::no;
    return reach;
}

UncertainParticle clamped_into(UncertainParticle q, const Box& box) {
    q.x = clamped(q.x, box.lower, box.upper);
    q.y = clamped(q.y, box.lower, box.upper);
    return q;
}

UncertainParticle moved(UncertainParticle q, const Uncertain& time, const Box& box) {
    q.x = q.x + q.vx * time;
    q.y = q.y + q.vy * time;
    return clamped_into(q, box);
}

// Calls `visit(on_x, on_y)` for every combination of hit axes the decisions
// allow (at least one axis hits).
template <typename Visit>
void for_each_hit(Tri on_x, Tri on_y, Visit visit) {
    for (const bool x : {false, true}) {
        for (const bool y : {false, true}) {
            if (!x && !y) continue;
            if ((x && on_x == Tri::no) || (!x && on_x == Tri::yes)) continue;
            if ((y && on_y == Tri::no) || (!y && on_y == Tri::yes)) continue;
            visit(x, y);
        }
    }
}

// rules.md "Rest of the step": move for `remaining`, stopping at a wall
// reached on the way.
UncertainParticle rest_of_step(const UncertainParticle& q, const Uncertain& remaining, const Box& box) {
    const WallReach reach = wall_reach(q, box, remaining);
    const Tri stops = at_most(reach.time, remaining);
    bool any = false;
    UncertainParticle result;
    const auto include = [&](const UncertainParticle& option) {
        result = any ? hull(result, option) : option;
        any = true;
    };
    if (stops != Tri::yes) include(moved(q, remaining, box));
    if (stops != Tri::no) {
        // It stops only on reaching the wall within the remaining time: a
        // creeping particle's open-ended reach is cut there.
        const Uncertain until_stop{std::min(reach.time.lo, remaining.hi), std::min(reach.time.hi, remaining.hi)};
        for_each_hit(reach.on_x, reach.on_y, [&](bool x, bool y) {
            UncertainParticle at_wall = moved(q, until_stop, box);
            if (x) at_wall.x = reach.wall_x;
            if (y) at_wall.y = reach.wall_y;
            include(at_wall);
        });
    }
    return any ? result : moved(q, remaining, box);
}

}  // namespace

UncertainParticle hull(const UncertainParticle& a, const UncertainParticle& b) {
    return {hull(a.x, b.x), hull(a.y, b.y), hull(a.vx, b.vx), hull(a.vy, b.vy)};
}

UncertainParticle uncertain_particle(const Particle& particle, double uncertainty) {
    const auto around = [&](double value) {
        // The value a program held is within `uncertainty` of what it printed,
        // and reading the printed text back adds half a unit in the last place.
        const double reading = uncertainty > 0.0 ? std::fabs(value) * 0x1p-52 : 0.0;
        return Uncertain::around(value, uncertainty + reading);
    };
    return {around(particle.position.x()), around(particle.position.y()), around(particle.velocity.x()),
            around(particle.velocity.y())};
}

Particle midpoint(const UncertainParticle& particle) {
    Particle p;
    p.position = Vec2(particle.x.mid(), particle.y.mid());
    p.velocity = Vec2(particle.vx.mid(), particle.vy.mid());
    return p;
}

TooManyPossiblePairs::TooManyPossiblePairs(std::size_t most)
    : std::runtime_error("more than " + std::to_string(most) +
                         " pairs of disks may collide in one step (disks piled on one another?), more than the "
                         "checker holds") {}

UncertainStep::UncertainStep(const Box& box, std::size_t most_pairs)
    : box_(box),
      most_pairs_(most_pairs != 0 ? most_pairs : ThreadCandidates::most_candidate_bytes() / bytes_per_possible_pair) {}

void UncertainStep::predict(std::span<const UncertainParticle> before, double duration) {
    before_ = before;
    duration_ = duration;
    candidates_.clear();
    const Uncertain step_end = Uncertain::exact(duration);
    for (std::uint32_t p = 0; p < before.size(); ++p) {
        const UncertainParticle q = clamped_into(before[p], box_);
        const WallReach reach = wall_reach(q, box_, step_end);
        const Tri exists = at_most(reach.time, step_end);
        if (exists == Tri::no) continue;
        PossibleCollision wall;
        wall.time = reach.time;
        wall.kind = CollisionKind::wall;
        wall.i = wall.j = p;
        wall.exists = exists;
        wall.on_x = reach.on_x;
        wall.on_y = reach.on_y;
        candidates_.push_back(wall);
    }
    find_candidate_pairs(before);

    // Each particle's candidates, for the selection and the fates.
    offsets_.assign(before.size() + 1, 0);
    for (const PossibleCollision& c : candidates_) {
        ++offsets_[c.i + 1];
        if (c.kind == CollisionKind::pair) ++offsets_[c.j + 1];
    }
    for (std::size_t p = 0; p < before.size(); ++p) offsets_[p + 1] += offsets_[p];
    listed_.resize(offsets_.back());
    std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
    for (std::uint32_t k = 0; k < candidates_.size(); ++k) {
        listed_[next[candidates_[k].i]++] = k;
        if (candidates_[k].kind == CollisionKind::pair) listed_[next[candidates_[k].j]++] = k;
    }
    select();
}

void UncertainStep::find_candidate_pairs(std::span<const UncertainParticle> before) {
    const std::size_t count = before.size();
    midpoints_.resize(count);
    double position_spread = 0.0;
    double velocity_spread = 0.0;
    double top_speed = 0.0;
    for (std::size_t p = 0; p < count; ++p) {
        midpoints_[p] = midpoint(before[p]);
        position_spread = std::max({position_spread, before[p].x.hi - before[p].x.lo, before[p].y.hi - before[p].y.lo});
        velocity_spread =
            std::max({velocity_spread, before[p].vx.hi - before[p].vx.lo, before[p].vy.hi - before[p].vy.lo});
        top_speed = std::max(top_speed, midpoints_[p].velocity.norm());
    }
    // Pairs that may come within 2r of each other: those within 2r + margin
    // by their midpoints, the margin covering how far two particles' bounds
    // and every formula's rounding let them be from their midpoints.
    const double margin = 4.0 * (position_spread + velocity_spread * duration_) + 0x1p-30 * box_.lower +
                          0x1p-40 * (box_.side + top_speed * duration_);
    const double reach = 2.0 * box_.lower + margin;
    const Box widened{box_.side, box_.lower + 0.5 * margin, box_.upper - 0.5 * margin, reach * reach};

    pair_keys_.clear();
    const auto key = [](std::uint32_t i, std::uint32_t j) {
        return (static_cast<std::uint64_t>(std::min(i, j)) << 32) | std::max(i, j);
    };
    // Pairs that meet within the step by their midpoints' paths...
    no_wall_.assign(count, never);
    const std::size_t most = most_pairs_;
    found_.resize(static_cast<std::size_t>(default_thread_count()));
    // (Each thread's list holds at most twice the most pairs: a pair may be
    // found in two slices.)
    for (ThreadCandidates& thread : found_) {
        thread.found.clear();
        thread.most_bytes = 2 * most * sizeof(Collision);
    }
    const PairSearchInput input{midpoints_, no_wall_, widened, duration_};
    try {
        search_.find_pairs(input, std::nullopt, found_);
    } catch (const std::bad_alloc&) {
        throw TooManyPossiblePairs(most);
    }
    const auto distinct_within_most = [&] {
        std::sort(pair_keys_.begin(), pair_keys_.end());
        pair_keys_.erase(std::unique(pair_keys_.begin(), pair_keys_.end()), pair_keys_.end());
        if (pair_keys_.size() > most) throw TooManyPossiblePairs(most);
    };
    for (const ThreadCandidates& thread : found_) {
        for (const Collision& c : thread.found) pair_keys_.push_back(key(c.i, c.j));
    }
    distinct_within_most();
    // ...and pairs within reach at the start however they move (a receding
    // or resting overlap may be approaching within rounding), each visited
    // once: more than the most distinct pairs past twice the most keys.
    positions_.resize(count);
    for (std::size_t p = 0; p < count; ++p) positions_[p] = midpoints_[p].position;
    for_each_close_pair(positions_, box_.side, reach, CloseIn::square, [&](std::uint32_t i, std::uint32_t j) {
        if (pair_keys_.size() >= 2 * most) throw TooManyPossiblePairs(most);
        pair_keys_.push_back(key(i, j));
    });
    distinct_within_most();
    for (const std::uint64_t k : pair_keys_)
        add_pair(static_cast<std::uint32_t>(k >> 32), static_cast<std::uint32_t>(k));
}

// rules.md "Pair candidate", every decision three-valued.
void UncertainStep::add_pair(std::uint32_t i, std::uint32_t j) {
    const UncertainParticle& a = before_[i];
    const UncertainParticle& b = before_[j];
    const Uncertain dpx = b.x - a.x, dpy = b.y - a.y;
    const Uncertain dvx = b.vx - a.vx, dvy = b.vy - a.vy;
    const Uncertain contact = Uncertain::exact(box_.contact_dist_sq);
    const Uncertain relative_speed_sq = square(dvx) + square(dvy);
    const Uncertain half_b = dpx * dvx + dpy * dvy;
    const Uncertain c = square(dpx) + square(dpy) - contact;
    const Uncertain cross = dpx * dvy - dpy * dvx;
    // Ours has no cancellation; the textbook B^2 - 4AC cancels terms of the
    // size of B^2, and a correct program may use it: its rounding is allowed.
    const Uncertain quarter_disc =
        textbook_cancellation(contact * relative_speed_sq - square(cross), half_b, relative_speed_sq, c);

    const bool surely_moving = dvx.lo > 0.0 || dvx.hi < 0.0 || dvy.lo > 0.0 || dvy.hi < 0.0;
    const bool surely_resting = dvx.lo == 0.0 && dvx.hi == 0.0 && dvy.lo == 0.0 && dvy.hi == 0.0;
    const Tri moving = surely_moving ? Tri::yes : (surely_resting ? Tri::no : Tri::maybe);
    const Tri approaching = tri_and(moving, half_b.below(0.0));
    const Tri touching = c.below_or_at(0.0);
    const Tri crossing = quarter_disc.above(0.0);
    Tri exists = tri_and(approaching, tri_or(touching, crossing));
    if (exists == Tri::no) return;

    Uncertain time = Uncertain::exact(0.0);
    if (touching != Tri::yes && crossing != Tri::no) {
        const Uncertain crossing_time = not_negative(c / (sqrt_of(quarter_disc) - half_b));
        time = touching == Tri::maybe ? hull(time, crossing_time) : crossing_time;
    }
    exists = tri_and(exists, time.below_or_at(duration_));
    if (exists == Tri::no) return;
    PossibleCollision pair;
    pair.time = time;
    pair.kind = CollisionKind::pair;
    pair.i = i;
    pair.j = j;
    pair.exists = exists;
    pair.touching = touching;
    pair.approaching = approaching;
    candidates_.push_back(pair);
}

Tri UncertainStep::comes_before(const PossibleCollision& a, const PossibleCollision& b) const {
    if (a.time.hi < b.time.lo) return Tri::yes;
    if (b.time.hi < a.time.lo) return Tri::no;
    // Bounds that only touch: at worst an exact tie, which the rest of the key decides.
    const bool a_key_first = std::tie(a.kind, a.i, a.j) < std::tie(b.kind, b.i, b.j);
    if (a.time.hi <= b.time.lo && a_key_first) return Tri::yes;
    if (b.time.hi <= a.time.lo && !a_key_first) return Tri::no;
    return Tri::maybe;
}

// rules.md "Select", where the order is decided: a candidate is accepted when
// it exists and nothing that may come before it may take one of its
// particles; rejected when something accepted surely comes before it.
void UncertainStep::select() {
    enum : std::int8_t { unknown = -1 };
    std::vector<std::int8_t> state(candidates_.size(), unknown);
    // By earliest time, then key.
    const auto key_order = [&](std::uint32_t a, std::uint32_t b) {
        const PossibleCollision& x = candidates_[a];
        const PossibleCollision& y = candidates_[b];
        return std::tie(x.time.lo, x.kind, x.i, x.j) < std::tie(y.time.lo, y.kind, y.i, y.j);
    };
    std::vector<std::uint32_t> order(candidates_.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), key_order);
    constexpr auto no = static_cast<std::int8_t>(Tri::no);
    constexpr auto yes = static_cast<std::int8_t>(Tri::yes);
    // Each particle's candidates in that order too, so that those that may
    // come before a candidate are a prefix of them; the candidates rejected
    // at its start are passed over once. And the one accepted (a particle has at most one: a second would have to
    // come surely before it, and was rejected when it was accepted). Without
    // these, a pile of k overlapping disks (every pair a candidate, each
    // particle k of them) cost k^3 comparisons a pass.
    std::vector<std::uint32_t> by_order = listed_;
    for (std::size_t p = 0; p + 1 < offsets_.size(); ++p) {
        std::sort(by_order.begin() + offsets_[p], by_order.begin() + offsets_[p + 1], key_order);
    }
    std::vector<std::uint32_t> undecided_from(offsets_.begin(), offsets_.end() - 1);
    constexpr std::uint32_t none = 0xffffffffU;
    std::vector<std::uint32_t> accepted_of(offsets_.size() - 1, none);
    // Whether nothing that may come before c, other than k itself, may take `particle`.
    const auto clear_of = [&](std::uint32_t particle, std::uint32_t k, const PossibleCollision& c) {
        std::uint32_t& from = undecided_from[particle];
        while (from < offsets_[particle + 1] && state[by_order[from]] == no) ++from;
        for (std::uint32_t at = from; at < offsets_[particle + 1]; ++at) {
            const std::uint32_t d = by_order[at];
            const PossibleCollision& other = candidates_[d];
            // From here on every candidate comes surely after c (comes_before() says no).
            if (std::tie(other.time.lo, other.kind, other.i, other.j) > std::tie(c.time.hi, c.kind, c.i, c.j)) break;
            if (d == k || state[d] == no) continue;
            if (comes_before(other, c) != Tri::no) return false;
        }
        return true;
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (const std::uint32_t k : order) {
            if (state[k] != unknown) continue;
            const PossibleCollision& c = candidates_[k];
            bool blocked = false;
            bool clear = true;
            for (const std::uint32_t particle : {c.i, c.j}) {
                const std::uint32_t taken = accepted_of[particle];
                if (taken != none && comes_before(candidates_[taken], c) == Tri::yes) blocked = true;
                if (clear && !clear_of(particle, k, c)) clear = false;
            }
            if (blocked || (clear && c.exists == Tri::yes)) {
                state[k] = blocked ? no : yes;
                if (!blocked) {
                    PARTICLESIM_ASSERT(accepted_of[c.i] == none && accepted_of[c.j] == none,
                                       "a particle has at most one accepted candidate");
                    accepted_of[c.i] = accepted_of[c.j] = k;
                }
                changed = true;
            }
        }
    }
    for (std::uint32_t k = 0; k < candidates_.size(); ++k) {
        candidates_[k].accepted = state[k] == unknown ? Tri::maybe : static_cast<Tri>(state[k]);
    }
}

std::span<const std::uint32_t> UncertainStep::candidates_of(std::uint32_t particle) const {
    return std::span<const std::uint32_t>(listed_).subspan(offsets_[particle],
                                                           offsets_[particle + 1] - offsets_[particle]);
}

bool UncertainStep::may_be_free(std::uint32_t particle) const {
    for (const std::uint32_t k : candidates_of(particle)) {
        const PossibleCollision& c = candidates_[k];
        if (c.accepted == Tri::yes) return false;
        // A wall candidate that surely exists is accepted unless an earlier
        // collision of the particle is: either way the particle collides.
        if (c.kind == CollisionKind::wall && c.exists == Tri::yes) return false;
    }
    return true;
}

UncertainParticle UncertainStep::outcome(std::uint32_t particle, int candidate) const {
    const UncertainParticle q = clamped_into(before_[particle], box_);
    const Uncertain step_end = Uncertain::exact(duration_);
    if (candidate < 0) return moved(q, step_end, box_);
    const PossibleCollision& c = candidates_[static_cast<std::size_t>(candidate)];
    // A candidate's time, as any program that accepts it computes it, lies in
    // [0, duration] (rules.md: a candidate when t <= the step's end): so does
    // the time it moves to, however little its bounds knew (a pair at rest
    // and touching within rounding may meet at any time from 0 on).
    const Uncertain when{std::clamp(c.time.lo, 0.0, duration_), std::clamp(c.time.hi, 0.0, duration_)};
    if (c.kind == CollisionKind::wall) {
        bool any = false;
        UncertainParticle result;
        const WallReach reach = wall_reach(q, box_, step_end);
        for_each_hit(c.on_x, c.on_y, [&](bool x, bool y) {
            UncertainParticle at_wall = moved(q, when, box_);
            if (x) {
                at_wall.x = reach.wall_x;
                at_wall.vx = -at_wall.vx;
            }
            if (y) {
                at_wall.y = reach.wall_y;
                at_wall.vy = -at_wall.vy;
            }
            const UncertainParticle option = rest_of_step(at_wall, step_end - when, box_);
            result = any ? hull(result, option) : option;
            any = true;
        });
        return result;
    }
    // rules.md "Pair at time t": both at contact, exchange along the line of centres.
    const UncertainParticle a = moved(clamped_into(before_[c.i], box_), when, box_);
    const UncertainParticle b = moved(clamped_into(before_[c.j], box_), when, box_);
    const Uncertain dx = b.x - a.x, dy = b.y - a.y;
    const Uncertain along = ((b.vx - a.vx) * dx + (b.vy - a.vy) * dy) / (square(dx) + square(dy));
    const Uncertain ex = along * dx, ey = along * dy;
    UncertainParticle mine = particle == c.i ? a : b;
    const double sign = particle == c.i ? 1.0 : -1.0;
    mine.vx = mine.vx + Uncertain::exact(sign) * ex;
    mine.vy = mine.vy + Uncertain::exact(sign) * ey;
    return rest_of_step(mine, step_end - when, box_);
}

void UncertainStep::fates_of(std::uint32_t particle, std::vector<Fate>& out) const {
    out.clear();
    if (may_be_free(particle)) out.push_back({-1, outcome(particle, -1)});
    for (const std::uint32_t k : candidates_of(particle)) {
        if (candidates_[k].accepted != Tri::no)
            out.push_back({static_cast<int>(k), outcome(particle, static_cast<int>(k))});
    }
}

}  // namespace particlesim
