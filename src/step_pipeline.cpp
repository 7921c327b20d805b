#include "step_pipeline.hpp"

#include "parallel.hpp"
#include "physics.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <numeric>

namespace particlesim {

namespace {

// The most ranges the wall candidates are gathered in (eight a thread).
constexpr std::int64_t max_wall_ranges = 256;

}  // namespace

void detect_wall_candidates(std::span<const Particle> particles, const Box& box, double duration,
                            std::span<double> wall_time, std::vector<Collision>& candidates, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    // Each range of particles counts its candidates, then writes them from
    // where the ranges before it end: in index order, on every thread. (A
    // range past the end, never visited, counts 0.)
    std::array<std::uint32_t, max_wall_ranges + 1> range_start{};
    const std::int64_t ranges = std::min<std::int64_t>(max_wall_ranges, 8 * std::int64_t{workers});
    const auto for_each_range = [&](auto&& body) { parallel_for_ranges(workers, count, ranges, body); };
    for_each_range([&](std::int64_t range, std::int64_t first, std::int64_t last) {
        std::uint32_t found = 0;
        for (std::int64_t i = first; i < last; ++i) {
            wall_time[i] = time_to_wall(particles[i].position, particles[i].velocity, box).time;
            found += wall_time[i] <= duration ? 1U : 0U;
        }
        range_start[range + 1] = found;
    });
    std::partial_sum(range_start.begin(), range_start.end(), range_start.begin());
    const std::size_t before = candidates.size();
    candidates.resize(before + range_start[ranges]);
    for_each_range([&](std::int64_t range, std::int64_t first, std::int64_t last) {
        std::size_t at = before + range_start[range];
        for (std::int64_t i = first; i < last; ++i) {
            if (wall_time[i] <= duration)
                candidates[at++] = Collision::wall(wall_time[i], static_cast<std::uint32_t>(i));
        }
    });
}

namespace {

// Candidates a parallel pass of the selection hands out at a time.
constexpr std::int64_t selection_block = 4096;

}  // namespace

StepCounts select_collisions(std::vector<Collision>& candidates, std::span<const ThreadCandidates> found,
                             const CandidateOrder& order, std::span<std::uint32_t> partner,
                             std::span<double> collision_time, SelectionScratch& scratch, int threads) {
    for (const ThreadCandidates& thread : found) {
        candidates.insert(candidates.end(), thread.found.begin(), thread.found.end());
    }
    std::span<std::uint32_t> earliest = scratch.earliest;
    // A pair found twice is two equal candidates: the first in place counts,
    // so that every thread count picks the same one.
    const auto comes_first = [&](std::uint32_t k, std::uint32_t other) {
        return order.before(candidates[k], candidates[other]) ||
               (k < other && !order.before(candidates[other], candidates[k]));
    };
    // Threads may claim one particle at the same time: then each claim is a
    // compare-and-swap, retried while it still comes first.
    const auto claim = [&](std::uint32_t particle, std::uint32_t k, bool shared) {
        if (!shared) {
            std::uint32_t& held = earliest[particle];
            if (held == no_collision || comes_first(k, held)) held = k;
            return;
        }
        std::atomic_ref<std::uint32_t> held(earliest[particle]);
        std::uint32_t current = held.load(std::memory_order_relaxed);
        while (current == no_collision || comes_first(k, current)) {
            if (held.compare_exchange_weak(current, k, std::memory_order_relaxed)) return;
        }
    };
    const auto is_free = [&](const Collision& c) {
        return partner[c.i] == no_collision && (c.kind == CollisionKind::wall || partner[c.j] == no_collision);
    };
    StepCounts counts;
    while (!candidates.empty()) {
        const auto count = static_cast<std::int64_t>(candidates.size());
        const std::int64_t blocks = (count + selection_block - 1) / selection_block;
        const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
        const bool shared = workers > 1;
        const auto for_each_block = [&](auto&& body) {
            parallel_for_blocks(workers, count, selection_block,
                                [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                                    body(block, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last));
                                });
        };
        for_each_block([&](std::int64_t, std::uint32_t first, std::uint32_t last) {
            for (std::uint32_t k = first; k < last; ++k) {
                claim(candidates[k].i, k, shared);
                if (candidates[k].kind == CollisionKind::pair) claim(candidates[k].j, k, shared);
            }
        });
        // Accepted collisions share no particle: each thread writes its own.
        scratch.block_counts.resize(static_cast<std::size_t>(blocks));
        for_each_block([&](std::int64_t block, std::uint32_t first, std::uint32_t last) {
            StepCounts& accepted = scratch.block_counts[block];
            accepted = {};
            for (std::uint32_t k = first; k < last; ++k) {
                const Collision& c = candidates[k];
                if (earliest[c.i] != k) continue;
                if (c.kind == CollisionKind::wall) {
                    partner[c.i] = wall_collision;
                    collision_time[c.i] = c.time;
                    ++accepted.wall_collisions;
                } else if (earliest[c.j] == k) {
                    partner[c.i] = c.j;
                    partner[c.j] = c.i;
                    collision_time[c.i] = c.time;
                    collision_time[c.j] = c.time;
                    ++accepted.particle_collisions;
                }
            }
        });
        for (const StepCounts& accepted : scratch.block_counts) counts += accepted;
        for_each_block([&](std::int64_t, std::uint32_t first, std::uint32_t last) {
            for (std::uint32_t k = first; k < last; ++k) {
                const Collision& c = candidates[k];
                std::atomic_ref<std::uint32_t>(earliest[c.i]).store(no_collision, std::memory_order_relaxed);
                if (c.kind == CollisionKind::pair) {
                    std::atomic_ref<std::uint32_t>(earliest[c.j]).store(no_collision, std::memory_order_relaxed);
                }
            }
        });
        // Accepted candidates and those they rule out leave; the rest go on,
        // in their order: each block keeps its own, then they close up.
        scratch.block_kept.resize(static_cast<std::size_t>(blocks));
        for_each_block([&](std::int64_t block, std::uint32_t first, std::uint32_t last) {
            const auto begin = candidates.begin() + first;
            const auto kept =
                std::remove_if(begin, candidates.begin() + last, [&](const Collision& c) { return !is_free(c); });
            scratch.block_kept[block] = static_cast<std::uint32_t>(kept - begin);
        });
        auto end = candidates.begin();
        for (std::int64_t block = 0; block < blocks; ++block) {
            const auto begin = candidates.begin() + block * selection_block;
            const auto kept_end = begin + scratch.block_kept[block];
            // A block with nothing dropped before it is in place already.
            end = end == begin ? kept_end : std::move(begin, kept_end, end);
        }
        candidates.erase(end, candidates.end());
    }
    return counts;
}

namespace {

// Both work on copies in registers and store each particle once: reading a
// coordinate pair back from memory right after storing its halves one by one
// stalls the processor (the load cannot be served from the pending stores).

void resolve_wall(Particle& particle, double time, const Box& box, double duration) {
    Particle moved = particle;
    // Recomputed from the unchanged start state, so it equals the candidate.
    const WallHit hit = time_to_wall(moved.position, moved.velocity, box);
    bounce_off_wall(moved, hit, box);
    move_stopping_at_wall(moved, duration - time, box);
    particle = moved;
}

// A pair's two particles, copied and moved to their contact at `time`.
struct PairAtContact {
    Particle* stored[2];
    Particle moved[2];
    double time;
};

PairAtContact at_contact(Particle& a, Particle& b, double time) {
    PairAtContact pair{{&a, &b}, {a, b}, time};
    for (Particle& p : pair.moved) p.position += p.velocity * time;
    return pair;
}

// After the exchange: the rest of the step, and each particle stored once.
void finish_pair(PairAtContact& pair, const Box& box, double duration) {
    for (Particle& p : pair.moved) {
        ++p.particle_collisions;
        clamp_into_box(p.position, box);
        move_stopping_at_wall(p, duration - pair.time, box);
    }
    *pair.stored[0] = pair.moved[0];
    *pair.stored[1] = pair.moved[1];
}

void resolve_pair(PairAtContact& pair, const Box& box, double duration) {
    Particle(&moved)[2] = pair.moved;
    exchange_normal_velocities(moved[0].position, moved[1].position, moved[0].velocity, moved[1].velocity);
    finish_pair(pair, box, duration);
}

// Two pairs at once, one in each lane of the exchange: the same bits as one
// at a time, in about the time of one.
void resolve_two_pairs(PairAtContact& first, PairAtContact& second, const Box& box, double duration) {
    const auto lanes = [&](auto component) { return TwoDoubles{component(first), component(second)}; };
    ContactPair<TwoDoubles> contact{
        lanes([](const PairAtContact& p) { return p.moved[0].position.x(); }),
        lanes([](const PairAtContact& p) { return p.moved[0].position.y(); }),
        lanes([](const PairAtContact& p) { return p.moved[1].position.x(); }),
        lanes([](const PairAtContact& p) { return p.moved[1].position.y(); }),
        lanes([](const PairAtContact& p) { return p.moved[0].velocity.x(); }),
        lanes([](const PairAtContact& p) { return p.moved[0].velocity.y(); }),
        lanes([](const PairAtContact& p) { return p.moved[1].velocity.x(); }),
        lanes([](const PairAtContact& p) { return p.moved[1].velocity.y(); }),
    };
    exchange_normal_components(contact);
    PairAtContact* pairs[2] = {&first, &second};
    for (int lane = 0; lane < 2; ++lane) {
        PairAtContact& pair = *pairs[lane];
        pair.moved[0].velocity = Vec2(contact.vix[lane], contact.viy[lane]);
        pair.moved[1].velocity = Vec2(contact.vjx[lane], contact.vjy[lane]);
        finish_pair(pair, box, duration);
    }
}

}  // namespace

void resolve_collisions(std::span<Particle> particles, std::span<const std::uint32_t> partner,
                        std::span<const double> collision_time, const Box& box, double duration, int threads) {
    constexpr std::int64_t partner_lookahead = 32;
    constexpr std::int64_t block = 1024;
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    // In storage order, reading only per-particle arrays: a large scene is
    // stored by position, so this walks memory instead of jumping through
    // it. A pair is resolved once, at its lower stored index; accepted
    // collisions share no particle, so they resolve independently (and the
    // exchange is symmetric, bit for bit, in its two particles). Pairs wait
    // for a second to share the exchange.
    parallel_for_blocks(workers, count, block, [&](std::int64_t, std::int64_t first, std::int64_t last) {
        PairAtContact pairs[2];
        int waiting = 0;
        for (std::int64_t i = first; i < last; ++i) {
            // A partner stored a row of cells ahead is a cache miss: fetch it
            // early, both lines a 48-byte particle may span.
            if (i + partner_lookahead < count && partner[i + partner_lookahead] < wall_collision) {
                const Particle& ahead = particles[partner[i + partner_lookahead]];
                __builtin_prefetch(&ahead);
                __builtin_prefetch(reinterpret_cast<const char*>(&ahead) + sizeof ahead - 1);
            }
            const std::uint32_t other = partner[i];
            if (other == no_collision) continue;
            if (other == wall_collision) {
                resolve_wall(particles[i], collision_time[i], box, duration);
            } else if (static_cast<std::uint32_t>(i) < other) {
                pairs[waiting++] = at_contact(particles[i], particles[other], collision_time[i]);
                if (waiting == 2) {
                    resolve_two_pairs(pairs[0], pairs[1], box, duration);
                    waiting = 0;
                }
            }
        }
        if (waiting == 1) resolve_pair(pairs[0], box, duration);
    });
}

void advance_free_particles(std::span<Particle> particles, std::span<std::uint32_t> partner, const Box& box,
                            double duration, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    parallel_for(workers, count, [&](std::int64_t i, std::size_t) {
        if (partner[i] == no_collision) {
            move_freely(particles[i], duration, box);
        } else {
            partner[i] = no_collision;
        }
    });
}

}  // namespace particlesim
