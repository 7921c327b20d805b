// The float-lane line test of the paths search: it never drops a pair whose
// lines come within the reach, at any scale, for grazing lines, nearly
// parallel motion and particles at rest; it drops most pairs that do not; and
// lines tested in blocks find what each finds alone, even where every line
// passes.

#include "check.hpp"

#include "core/random.hpp"
#include "search/path_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <vector>

using namespace particlesim;

namespace {

// Whether the relative line of (i, j) passes within `reach` of the origin,
// in long double from the doubles (|dp x dv| <= reach |dv|; at rest: |dp|).
bool lines_within(const Particle& a, const Particle& b, double reach) {
    using Long = long double;
    const Long dx = Long(b.position.x()) - a.position.x();
    const Long dy = Long(b.position.y()) - a.position.y();
    const Long dvx = Long(b.velocity.x()) - a.velocity.x();
    const Long dvy = Long(b.velocity.y()) - a.velocity.y();
    const Long speed = std::sqrt(dvx * dvx + dvy * dvy);
    if (speed == 0) return std::sqrt(dx * dx + dy * dy) <= reach;
    return std::abs(dx * dvy - dy * dvx) <= Long(reach) * speed;
}

struct Trial {
    Box box;
    double reach = 0.0;
    std::vector<Particle> particles;
};

// Particles in a box of side 2^scale, speeds spread over `speed_decades`
// decades below 2^(scale + speed_shift); every fourth particle is placed so
// that its line grazes particle 0's at (1 - 2^-k) or (1 + 2^-k) times the
// reach, every seventh moves as particle 0 does but for a tiny difference,
// and a few rest.
Trial make_trial(SplitMix64& rng, int scale, int speed_shift, double speed_decades) {
    Trial t;
    const double side = std::ldexp(1.0, scale);
    const double radius = side * std::pow(10.0, -1.0 - 6.0 * rng.uniform());
    t.box = Box::of(World{side, radius});
    t.reach = contact_reach(t.box);
    const auto coordinate = [&] { return t.box.lower + (t.box.upper - t.box.lower) * rng.uniform(); };
    const auto speed = [&] {
        return std::ldexp(1.0, scale + speed_shift) * std::pow(10.0, -speed_decades * rng.uniform());
    };
    const auto direction = [&] { return 6.283185307179586 * rng.uniform(); };
    const int count = 40;
    for (int i = 0; i < count; ++i) {
        Particle p;
        p.position = Vec2(coordinate(), coordinate());
        const double s = i % 11 == 5 ? 0.0 : speed();
        const double a = direction();
        p.velocity = Vec2(s * std::cos(a), s * std::sin(a));
        t.particles.push_back(p);
    }
    const Particle& first = t.particles[0];
    for (int i = 4; i < count; i += 4) {
        // A relative line at distance (1 -+ 2^-k) reach from particle 0.
        Particle& p = t.particles[static_cast<std::size_t>(i)];
        const Vec2 dv = p.velocity - first.velocity;
        if (dv.norm() == 0.0) continue;
        const Vec2 along = dv / dv.norm();
        const Vec2 across(-along.y(), along.x());
        const double k = std::ldexp(1.0, -static_cast<int>(rng.next() % 40));
        const double distance = t.reach * (i % 8 == 0 ? 1.0 - k : 1.0 + k);
        const double offset = (rng.uniform() - 0.5) * side;
        p.position = first.position + across * distance + along * offset;
    }
    for (int i = 7; i < count; i += 7) {
        Particle& p = t.particles[static_cast<std::size_t>(i)];
        const double tiny = std::ldexp(std::abs(first.velocity.x()) + 1e-300, -10 - static_cast<int>(rng.next() % 40));
        p.velocity = first.velocity + Vec2(tiny, -tiny);
    }
    return t;
}

// Whether this processor runs the `lanes`-lane test; says so when it does not.
bool lanes_run_here(int lanes) {
    if (PathLines::supports_lanes(lanes)) return true;
    std::printf("test_path_lines: no %d-lane test on this processor, not run\n", lanes);
    return false;
}

void never_drops_a_pair_within_reach(int lanes) {
    if (!lanes_run_here(lanes)) return;
    SplitMix64 rng(15);
    long dropped = 0;
    long within = 0;
    long passed = 0;
    long pairs = 0;
    std::vector<std::uint32_t> near;
    for (int trial = 0; trial < 3000; ++trial) {
        // Boxes from 2^-60 to 2^60, speeds up to 2^20 boxes a step and down
        // to 1e-12 of that.
        const int scale = -60 + static_cast<int>(rng.next() % 121);
        const int speed_shift = -20 + static_cast<int>(rng.next() % 41);
        const Trial t = make_trial(rng, scale, speed_shift, 12.0 * rng.uniform());
        PathLines lines(lanes);
        lines.assign(t.particles, t.box);
        for (std::uint32_t i = 0; i < t.particles.size(); ++i) {
            near.clear();
            lines.gather_near(i, near);
            CHECK(std::is_sorted(near.begin(), near.end()));
            for (std::uint32_t j = 0; j < t.particles.size(); ++j) {
                if (j == i) continue;
                ++pairs;
                const bool found = std::binary_search(near.begin(), near.end(), j);
                passed += found ? 1 : 0;
                if (!lines_within(t.particles[i], t.particles[j], t.reach)) continue;
                ++within;
                if (!found) {
                    ++dropped;
                    const check::Context context("trial ", trial, ", pair ", i, " ", j);
                    CHECK(found);
                }
            }
            CHECK(std::find(near.begin(), near.end(), i) == near.end());
        }
        // Blocks of two to four lines give each line what it gives alone.
        std::vector<std::uint32_t> alone;
        for (std::uint32_t first = 0; first + 4 <= t.particles.size(); first += 4) {
            const std::uint32_t size = 2 + static_cast<std::uint32_t>(rng.next() % 3);
            std::vector<std::uint32_t> block;
            for (std::uint32_t k = 0; k < size; ++k) block.push_back(first + k);
            std::array<std::vector<std::uint32_t>, 4> found;
            std::array<std::vector<std::uint32_t>*, 4> nears{&found[0], &found[1], &found[2], &found[3]};
            lines.gather_near_block(block, std::span(nears).first(size));
            for (std::uint32_t k = 0; k < size; ++k) {
                alone.clear();
                lines.gather_near(block[k], alone);
                CHECK(found[k] == alone);
            }
        }
    }
    CHECK_EQ(dropped, 0L);
    CHECK(within > 20000);  // the grazing lines alone are thousands
    // Useful: few pairs pass that are not within reach (at rest, parallel
    // motion and grazes at 1 + 2^-k pass, by design).
    CHECK(passed - within < pairs / 5);
}

// A crowd within a quarter of the reach: every line passes every other, so
// that a scan notes more groups with a passing line than its notes hold, and
// appends them in several runs; every line is found, in order, alone, in
// blocks and arranged.
void a_crowd_finds_every_line(int lanes) {
    if (!lanes_run_here(lanes)) return;
    SplitMix64 rng(19);
    const Box box = Box::of(World{1000.0, 1.0});
    const double reach = contact_reach(box);
    std::vector<Particle> particles(3001);
    for (Particle& p : particles) {
        const double a = 6.283185307179586 * rng.uniform();
        const double d = 0.25 * reach * rng.uniform();
        p.position = Vec2(500.0 + d * std::cos(a), 500.0 + d * std::sin(a));
        p.velocity = Vec2(rng.uniform() - 0.5, rng.uniform() - 0.5);
    }
    const auto count = static_cast<std::uint32_t>(particles.size());
    PathLines lines(lanes);
    lines.assign(particles, box);
    std::vector<std::uint32_t> near;
    std::vector<std::uint32_t> others;
    for (const std::uint32_t i : {0U, 1U, 17U, 1500U, count - 1}) {
        near.clear();
        lines.gather_near(i, near);
        others.clear();
        for (std::uint32_t j = 0; j < count; ++j) {
            if (j != i) others.push_back(j);
        }
        const check::Context context("line ", i);
        CHECK(near == others);
    }
    std::array<std::vector<std::uint32_t>, 4> found;
    std::array<std::vector<std::uint32_t>*, 4> nears{&found[0], &found[1], &found[2], &found[3]};
    const std::array<std::uint32_t, 4> block{3, 4, 900, 2999};
    lines.gather_near_block(block, nears);
    for (std::size_t k = 0; k < block.size(); ++k) {
        near.clear();
        lines.gather_near(block[k], near);
        CHECK(found[k] == near);
    }
    // Every third line new: each new line finds every old one.
    std::vector<std::uint32_t> old_lines;
    std::vector<std::uint32_t> new_lines;
    for (std::uint32_t i = 0; i < count; ++i) (i % 3 == 0 ? new_lines : old_lines).push_back(i);
    lines.arrange(particles, old_lines, new_lines);
    for (std::size_t first = 0; first < new_lines.size(); first += 4) {
        const std::size_t size = std::min<std::size_t>(4, new_lines.size() - first);
        for (auto& list : found) list.clear();
        lines.gather_new_block(first, std::span(nears).first(size));
        for (std::size_t k = 0; k < size; ++k) {
            const check::Context context("new line ", new_lines[first + k]);
            std::sort(found[k].begin(), found[k].end());
            CHECK(std::includes(found[k].begin(), found[k].end(), old_lines.begin(), old_lines.end()));
            CHECK(!std::binary_search(found[k].begin(), found[k].end(), new_lines[first + k]));
        }
    }
}

// Moving every point along its line, and replacing lines one by one, gives
// the lines assign() makes from the same particles.
void moved_and_set_lines_are_assigned_lines() {
    SplitMix64 rng(16);
    std::vector<std::uint32_t> near_assigned;
    std::vector<std::uint32_t> near_updated;
    for (int trial = 0; trial < 200; ++trial) {
        Trial t = make_trial(rng, 14, -2, 2.0);
        const auto into_box = [&](Particle& p) { p.position = p.position.cwiseMax(t.box.lower).cwiseMin(t.box.upper); };
        std::for_each(t.particles.begin(), t.particles.end(), into_box);
        PathLines updated;
        updated.assign(t.particles, t.box);
        // Inside the box, and the same fastest speed: the same scales and margins.
        for (Particle& p : t.particles) {
            p.position = p.position + p.velocity * 1e-3;
            into_box(p);
        }
        updated.move_each([&](std::uint32_t i) { return t.particles[i].position; });
        for (std::uint32_t i = 0; i < t.particles.size(); i += 3) {
            t.particles[i].velocity = -t.particles[i].velocity;
            updated.set(i, t.particles[i].position, t.particles[i].velocity);
        }
        PathLines assigned;
        assigned.assign(t.particles, t.box);
        for (std::uint32_t i = 0; i < t.particles.size(); ++i) {
            near_assigned.clear();
            near_updated.clear();
            assigned.gather_near(i, near_assigned);
            updated.gather_near(i, near_updated);
            CHECK(near_assigned == near_updated);
        }
    }
}

// arrange() and gather_new_block(): every pair gather_near() finds for a
// new line, with an old line from the new line, with a new line from one
// side or both; no other pair, no padding, never the line itself; on every
// lane width, old and new lines mixed at random (all new, as made afresh,
// included).
void arranged_new_lines_find_what_each_finds(int lanes) {
    if (!lanes_run_here(lanes)) return;
    SplitMix64 rng(17);
    long found_pairs = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Trial t = make_trial(rng, -20 + static_cast<int>(rng.next() % 41), -2, 3.0);
        // More particles than a group, so that blocks start inside groups.
        for (int copy = 0; copy < 2; ++copy) {
            const Trial more = make_trial(rng, 0, -2, 3.0);
            for (const Particle& p : more.particles) {
                Particle scaled = p;
                const double scale = t.box.side / more.box.side;
                scaled.position = p.position * scale;
                scaled.velocity = p.velocity * scale;
                t.particles.push_back(scaled);
            }
        }
        const auto count = static_cast<std::uint32_t>(t.particles.size());
        PathLines identity(lanes);
        identity.assign(t.particles, t.box);
        PathLines arranged(lanes);
        arranged.assign(t.particles, t.box);
        std::vector<std::uint32_t> old_lines;
        std::vector<std::uint32_t> new_lines;
        const std::uint64_t share = trial % 5 == 0 ? 8 : rng.next() % 8;  // of 8 new
        for (std::uint32_t i = 0; i < count; ++i) (rng.next() % 8 < share ? new_lines : old_lines).push_back(i);
        arranged.arrange(t.particles, old_lines, new_lines);
        std::vector<char> is_new(count, 0);
        for (const std::uint32_t i : new_lines) is_new[i] = 1;
        // Every new line's finds, in blocks of 1 to 4.
        std::vector<std::vector<std::uint32_t>> finds(new_lines.size());
        for (std::size_t first = 0; first < new_lines.size();) {
            const std::size_t size = std::min<std::size_t>(1 + rng.next() % 4, new_lines.size() - first);
            std::array<std::vector<std::uint32_t>*, 4> nears{};
            for (std::size_t k = 0; k < size; ++k) nears[k] = &finds[first + k];
            arranged.gather_new_block(first, std::span(nears).first(size));
            first += size;
        }
        const auto finds_of = [&](std::uint32_t i) -> const std::vector<std::uint32_t>& {
            return finds[static_cast<std::size_t>(std::lower_bound(new_lines.begin(), new_lines.end(), i) -
                                                  new_lines.begin())];
        };
        const auto has = [](const std::vector<std::uint32_t>& list, std::uint32_t j) {
            return std::find(list.begin(), list.end(), j) != list.end();
        };
        std::vector<std::uint32_t> near;
        for (const std::uint32_t i : new_lines) {
            near.clear();
            identity.gather_near(i, near);
            const std::vector<std::uint32_t>& found = finds_of(i);
            const check::Context context("trial ", trial, ", line ", i);
            for (const std::uint32_t j : near) {
                ++found_pairs;
                CHECK(has(found, j) || (is_new[j] != 0 && has(finds_of(j), i)));
            }
            for (const std::uint32_t j : found) CHECK(j < count && j != i && has(near, j));
        }
    }
    CHECK(found_pairs > 1000);
    // A block past the new lines, or after assign() made the slots
    // particles again, is refused.
    SplitMix64 rng_misuse(18);
    const Trial t = make_trial(rng_misuse, 0, -2, 3.0);
    PathLines lines(lanes);
    lines.assign(t.particles, t.box);
    const std::vector<std::uint32_t> old_lines{0, 1, 2};
    std::vector<std::uint32_t> new_lines;
    for (std::uint32_t i = 3; i < t.particles.size(); ++i) new_lines.push_back(i);
    lines.arrange(t.particles, old_lines, new_lines);
    std::vector<std::uint32_t> near;
    std::array<std::vector<std::uint32_t>*, 1> one{&near};
    const auto refused = [&](std::size_t first) {
        try {
            lines.gather_new_block(first, one);
        } catch (const std::invalid_argument&) {
            return true;
        }
        return false;
    };
    CHECK(!refused(new_lines.size() - 1));
    CHECK(refused(new_lines.size()));
    lines.assign(t.particles, t.box);
    CHECK(refused(0));
}

// arrange_changed() makes the layout arrange() makes from the lists the
// collision counts give (in lanes where the processor has them): the same
// new lines, the counts updated, and every block of new lines finding the
// same lines in the same order; for every particle count (the last few past
// a whole four), arranged again and again, and with every line new.
void lines_arranged_from_counts_are_the_lists(int lanes) {
    if (!lanes_run_here(lanes)) return;
    SplitMix64 rng(29);
    long blocks = 0;
    for (int trial = 0; trial < 120; ++trial) {
        Trial t = make_trial(rng, -10 + static_cast<int>(rng.next() % 21), -2, 3.0);
        t.particles.resize(std::min<std::size_t>(t.particles.size(), 1 + rng.next() % 300));
        const auto count = static_cast<std::uint32_t>(t.particles.size());
        PathLines from_lists(lanes);
        PathLines from_counts(lanes);
        from_lists.assign(t.particles, t.box);
        from_counts.assign(t.particles, t.box);
        std::vector<std::uint64_t> counts(count);
        for (std::uint64_t& c : counts) c = rng.next() % 4;
        for (int round = 0; round < 4; ++round) {
            for (Particle& p : t.particles) {
                p.particle_collisions = rng.next() % 3;
                p.wall_collisions = rng.next() % 3;
            }
            // A new line faster than any before, so that the largest speed moves.
            double fastest = 0.0;
            for (const Particle& p : t.particles) fastest = std::max(fastest, p.velocity.cwiseAbs().maxCoeff());
            Particle& faster = t.particles[rng.next() % count];
            faster.velocity = Vec2(1.1 * fastest, -0.5 * fastest);
            faster.wall_collisions += 1;
            const bool all_new = round == 0 && trial % 4 == 0;
            std::vector<std::uint32_t> old_lines;
            std::vector<std::uint32_t> new_lines;
            std::vector<std::uint64_t> updated = counts;
            for (std::uint32_t i = 0; i < count; ++i) {
                const std::uint64_t total = t.particles[i].particle_collisions + t.particles[i].wall_collisions;
                (all_new || total != counts[i] ? new_lines : old_lines).push_back(i);
                updated[i] = total;
            }
            from_lists.arrange(t.particles, old_lines, new_lines);
            std::vector<std::uint32_t> changed{7, 7, 7};  // replaced, not appended to
            from_counts.arrange_changed(t.particles, counts, all_new, changed);
            const check::Context context("trial ", trial, ", round ", round);
            CHECK(changed == new_lines);
            CHECK(counts == updated);
            CHECK(from_counts.largest_coordinate() == from_lists.largest_coordinate());
            CHECK(from_counts.largest_speed() == from_lists.largest_speed());
            for (std::size_t first = 0; first < new_lines.size(); first += 4) {
                const std::size_t size = std::min<std::size_t>(4, new_lines.size() - first);
                std::array<std::vector<std::uint32_t>, 4> listed;
                std::array<std::vector<std::uint32_t>, 4> counted;
                std::array<std::vector<std::uint32_t>*, 4> listed_nears{&listed[0], &listed[1], &listed[2], &listed[3]};
                std::array<std::vector<std::uint32_t>*, 4> counted_nears{&counted[0], &counted[1], &counted[2],
                                                                         &counted[3]};
                from_lists.gather_new_block(first, std::span(listed_nears).first(size));
                from_counts.gather_new_block(first, std::span(counted_nears).first(size));
                CHECK(listed == counted);
                ++blocks;
            }
        }
    }
    CHECK(blocks > 1000);
}

}  // namespace

int main(int argc, char** argv) {
    return check::run(
        argc, argv, "test_path_lines",
        {{"never drops a pair within reach, 4 lanes", [] { never_drops_a_pair_within_reach(4); }},
         {"never drops a pair within reach, 8 lanes", [] { never_drops_a_pair_within_reach(8); }},
         {"never drops a pair within reach, 16 lanes", [] { never_drops_a_pair_within_reach(16); }},
         {"a crowd finds every line, 4 lanes", [] { a_crowd_finds_every_line(4); }},
         {"a crowd finds every line, 8 lanes", [] { a_crowd_finds_every_line(8); }},
         {"a crowd finds every line, 16 lanes", [] { a_crowd_finds_every_line(16); }},
         {"moved and set lines are assigned lines", moved_and_set_lines_are_assigned_lines},
         {"arranged new lines find what each finds, 4 lanes", [] { arranged_new_lines_find_what_each_finds(4); }},
         {"arranged new lines find what each finds, 8 lanes", [] { arranged_new_lines_find_what_each_finds(8); }},
         {"arranged new lines find what each finds, 16 lanes", [] { arranged_new_lines_find_what_each_finds(16); }},
         {"lines arranged from counts are the lists, 4 lanes", [] { lines_arranged_from_counts_are_the_lists(4); }},
         {"lines arranged from counts are the lists, 16 lanes", [] { lines_arranged_from_counts_are_the_lists(16); }}});
}
