#pragma once
// A second, independent implementation of the step rules, written the way a
// student would from rules.md alone: textbook formulas (the unit normal, the
// discriminant B^2 - 4AC, t = 2C / (-B + sqrt(disc))), every pair tested,
// printf for the output. It rounds differently from the library, so on a
// crowded scene its output drifts away from ours by chaos while every step
// still follows the rules: exactly what simcheck must accept. Each classic
// mistake can be injected, for simcheck to catch.

#include "particlesim/particle.hpp"
#include "particlesim/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace textbook {

enum class Mistake {
    none,
    no_stop_at_wall,          // after a collision, a wall in the rest of the step reflects the disk at once
    ties_by_index_only,       // equal times ordered by particle indices, walls not first
    overlaps_never_collide,   // a pair touching or overlapping at the start is never a candidate
    two_collisions_per_step,  // a particle may take part in two collisions in a step
    corner_flips_one_axis,    // a corner hit flips vx only
    pruned_search,            // only pairs starting within 2r + max(|v|) / 4 are tested
    counters_off_by_one,      // the final pc of the first particle that collided is one short
    dropped_line,             // one line of a middle step is left out
    repeated_line,            // one line of a middle step is written twice
};

inline const char* mistake_name(Mistake m) {
    switch (m) {
    case Mistake::none: return "none";
    case Mistake::no_stop_at_wall: return "no stop at the wall";
    case Mistake::ties_by_index_only: return "ties broken by index only";
    case Mistake::overlaps_never_collide: return "overlapping pairs never collide";
    case Mistake::two_collisions_per_step: return "two collisions per step";
    case Mistake::corner_flips_one_axis: return "a corner flips one axis";
    case Mistake::pruned_search: return "a pruned search";
    case Mistake::counters_off_by_one: return "counters off by one";
    case Mistake::dropped_line: return "a dropped line";
    case Mistake::repeated_line: return "a repeated line";
    }
    return "";
}

struct Disk {
    double x, y, vx, vy;
    unsigned long long pc = 0, wc = 0;
};

class Simulator {
public:
    Simulator(double box, double radius, std::vector<Disk> disks, Mistake mistake, int substeps)
        : box_(box), r_(radius), disks_(std::move(disks)), mistake_(mistake), substeps_(substeps) {}

    void step() {
        for (int k = 0; k < substeps_; ++k) micro_step(1.0 / substeps_);
    }
    [[nodiscard]] const std::vector<Disk>& disks() const { return disks_; }

private:
    struct Candidate {
        double t;
        int kind;  // 0 wall, 1 pair
        std::size_t i, j;
        bool on_x, on_y;
    };

    double wall_time(double p, double v) const {
        if (v < 0) return (r_ - p) / v;
        if (v > 0) return (box_ - r_ - p) / v;
        return INFINITY;
    }

    void micro_step(double dt) {
        const std::size_t n = disks_.size();
        std::vector<Candidate> candidates;
        double fastest = 0;
        for (const Disk& d : disks_) fastest = std::max(fastest, std::hypot(d.vx, d.vy));
        for (std::size_t i = 0; i < n; ++i) {
            const Disk& d = disks_[i];
            const double tx = wall_time(d.x, d.vx), ty = wall_time(d.y, d.vy);
            const double t = std::min(tx, ty);
            if (t <= dt) candidates.push_back({t, 0, i, i, tx == t, ty == t});
            for (std::size_t j = i + 1; j < n; ++j) {
                const Disk& e = disks_[j];
                const double dx = e.x - d.x, dy = e.y - d.y, dvx = e.vx - d.vx, dvy = e.vy - d.vy;
                if (mistake_ == Mistake::pruned_search && std::hypot(dx, dy) > 2 * r_ + fastest * dt / 4) continue;
                const double A = dvx * dvx + dvy * dvy;
                const double B = 2 * (dx * dvx + dy * dvy);
                const double C = dx * dx + dy * dy - 4 * r_ * r_;
                if (A == 0) continue;
                if (C <= 0) {
                    if (B < 0 && mistake_ != Mistake::overlaps_never_collide)
                        candidates.push_back({0.0, 1, i, j, false, false});
                    continue;
                }
                if (B >= 0) continue;
                const double disc = B * B - 4 * A * C;
                if (disc <= 0) continue;
                const double t = 2 * C / (-B + std::sqrt(disc));
                if (t <= dt) candidates.push_back({t, 1, i, j, false, false});
            }
        }
        std::sort(candidates.begin(), candidates.end(), [&](const Candidate& a, const Candidate& b) {
            if (mistake_ == Mistake::ties_by_index_only) return std::tie(a.t, a.i, a.j) < std::tie(b.t, b.i, b.j);
            return std::tie(a.t, a.kind, a.i, a.j) < std::tie(b.t, b.kind, b.i, b.j);
        });
        const int allowed = mistake_ == Mistake::two_collisions_per_step ? 2 : 1;
        std::vector<int> taken(n, 0);
        std::vector<Candidate> accepted;
        for (const Candidate& c : candidates) {
            if (taken[c.i] < allowed && taken[c.j] < allowed) {
                ++taken[c.i];
                if (c.kind == 1) ++taken[c.j];
                accepted.push_back(c);
            }
        }
        // Carried out in time order; each collided disk remembers how far in
        // time it has got (with one collision a disk, simply t).
        std::vector<double> reached(n, 0.0);
        const auto move_to = [&](std::size_t k, double t) {
            disks_[k].x += disks_[k].vx * (t - reached[k]);
            disks_[k].y += disks_[k].vy * (t - reached[k]);
            reached[k] = t;
        };
        for (const Candidate& c : accepted) {
            if (c.kind == 0) {
                move_to(c.i, c.t);
                Disk& d = disks_[c.i];
                const bool flip_y = c.on_y && !(mistake_ == Mistake::corner_flips_one_axis && c.on_x);
                if (c.on_x) {
                    d.x = d.vx < 0 ? r_ : box_ - r_;
                    d.vx = -d.vx;
                }
                if (c.on_y) d.y = d.vy < 0 ? r_ : box_ - r_;
                if (flip_y) d.vy = -d.vy;
                ++d.wc;
            } else {
                move_to(c.i, c.t);
                move_to(c.j, c.t);
                Disk& a = disks_[c.i];
                Disk& b = disks_[c.j];
                const double dist = std::hypot(b.x - a.x, b.y - a.y);
                if (dist > 0) {
                    const double nx = (b.x - a.x) / dist, ny = (b.y - a.y) / dist;
                    const double along = (b.vx - a.vx) * nx + (b.vy - a.vy) * ny;
                    a.vx += along * nx;
                    a.vy += along * ny;
                    b.vx -= along * nx;
                    b.vy -= along * ny;
                }
                ++a.pc;
                ++b.pc;
            }
        }
        for (std::size_t k = 0; k < n; ++k) {
            Disk& d = disks_[k];
            if (taken[k] == 0) {
                d.x = std::clamp(d.x + d.vx * dt, r_, box_ - r_);
                d.y = std::clamp(d.y + d.vy * dt, r_, box_ - r_);
                continue;
            }
            const double remaining = dt - reached[k];
            const double tx = wall_time(d.x, d.vx), ty = wall_time(d.y, d.vy);
            const double t = std::min(tx, ty);
            if (t <= remaining && mistake_ != Mistake::no_stop_at_wall) {
                d.x += d.vx * t;
                d.y += d.vy * t;
                if (tx == t) d.x = d.vx < 0 ? r_ : box_ - r_;
                if (ty == t) d.y = d.vy < 0 ? r_ : box_ - r_;
            } else {
                d.x += d.vx * remaining;
                d.y += d.vy * remaining;
                if (t <= remaining) {  // no_stop_at_wall: reflected off the wall at once
                    if (d.x < r_ || d.x > box_ - r_) {
                        d.x = d.x < r_ ? 2 * r_ - d.x : 2 * (box_ - r_) - d.x;
                        d.vx = -d.vx;
                    }
                    if (d.y < r_ || d.y > box_ - r_) {
                        d.y = d.y < r_ ? 2 * r_ - d.y : 2 * (box_ - r_) - d.y;
                        d.vy = -d.vy;
                    }
                }
            }
            d.x = std::clamp(d.x, r_, box_ - r_);
            d.y = std::clamp(d.y, r_, box_ - r_);
        }
    }

    double box_, r_;
    std::vector<Disk> disks_;
    Mistake mistake_;
    int substeps_;
};

inline std::string fixed8(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.8f", v);
    return std::string(text) == "-0.00000000" ? "0.00000000" : text;
}

// The whole output of a print- or perf-mode run, with the mistake injected.
inline std::string output(const particlesim::Scene& scene, const std::vector<particlesim::Particle>& start,
                          Mistake mistake = Mistake::none, int substeps = 1) {
    std::vector<Disk> disks;
    for (const auto& p : start) disks.push_back({p.position.x(), p.position.y(), p.velocity.x(), p.velocity.y()});
    Simulator sim(scene.world.box_size, scene.world.radius, disks, mistake, substeps);
    const std::int64_t steps = scene.steps;
    const std::int64_t odd_step = std::max<std::int64_t>(steps / 2, 1);
    const std::size_t odd_particle = start.size() / 2;
    std::string out;
    const auto block = [&](std::int64_t s, bool final_block) {
        const auto& d = sim.disks();
        bool short_one = mistake == Mistake::counters_off_by_one;
        for (std::size_t i = 0; i < d.size(); ++i) {
            std::string line = std::to_string(s);
            line += ' ';
            line += std::to_string(i);
            for (const double value : {d[i].x, d[i].y, d[i].vx, d[i].vy}) {
                line += ' ';
                line += fixed8(value);
            }
            if (final_block) {
                unsigned long long pc = d[i].pc;
                if (short_one && pc > 0) {
                    --pc;
                    short_one = false;
                }
                for (const unsigned long long counter : {pc, d[i].wc}) {
                    line += ' ';
                    line += std::to_string(counter);
                }
            }
            line += "\n";
            const bool odd = s == odd_step && i == odd_particle && !final_block;
            if (odd && mistake == Mistake::dropped_line) continue;
            out += line;
            if (odd && mistake == Mistake::repeated_line) out += line;
        }
    };
    block(0, false);
    for (std::int64_t s = 1; s <= steps; ++s) {
        sim.step();
        if (scene.mode == particlesim::OutputMode::print && s < steps) block(s, false);
    }
    block(steps, true);
    return out;
}

}  // namespace textbook
