#include "step_pipeline.hpp"

#include "parallel.hpp"
#include "physics.hpp"
#include "prefetch.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <stdexcept>

namespace particlesim {

void measure_step_start(std::span<const Particle> particles, const Box& box, double duration,
                        std::span<double> wall_time, StepStart& start, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    start.resize(particles.size());
    start.with_or_without_motion([&](auto with_motion) {
        parallel_for_blocks(workers, count, motion_block,
                            [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                                BlockStart measured;
                                for (std::int64_t i = first; i < last; ++i) {
                                    wall_time[i] = measured.measure<with_motion>(particles[i], box, duration);
                                }
                                start.blocks[block] = measured;
                            });
    });
    start.measured = true;
}

void gather_wall_candidates(std::span<const double> wall_time, double duration, StepStart& start,
                            std::vector<Collision>& candidates, int threads) {
    const auto count = static_cast<std::int64_t>(wall_time.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    // Each block writes its candidates from where the blocks before it end: in index order, on every thread.
    const std::size_t before = candidates.size();
    std::uint32_t found = 0;
    for (std::size_t block = 0; block < start.blocks.size(); ++block) {
        start.first_candidate[block] = found;
        found += start.blocks[block].wall_candidates;
    }
    candidates.resize(before + found);
    parallel_for_blocks(workers, count, motion_block, [&](std::int64_t block, std::int64_t first, std::int64_t last) {
        std::size_t at = before + start.first_candidate[block];
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
    // Whether candidate k comes before the one a particle holds (or it
    // holds none). Without branches on either: which way it goes follows no
    // pattern. Times decide all but ties, which take the full order.
    const auto takes_over = [&](std::uint32_t k, std::uint32_t held) -> bool {
        const bool none = held == no_collision;
        const double time = candidates[k].time;
        const double held_time = candidates[none ? k : held].time;
        const bool tie = !none & (time == held_time);
        if (tie) [[unlikely]]
            return comes_first(k, held);
        return none | (time < held_time);
    };
    const auto claim = [&](std::uint32_t particle, std::uint32_t k) {
        std::uint32_t& held = earliest[particle];
        held = takes_over(k, held) ? k : held;
    };
    const auto is_free = [&](const Collision& c) {
        return partner[c.i] == no_collision && (c.kind == CollisionKind::wall || partner[c.j] == no_collision);
    };
    StepCounts counts;
    while (!candidates.empty()) {
        const auto count = static_cast<std::int64_t>(candidates.size());
        const std::int64_t blocks = (count + selection_block - 1) / selection_block;
        const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
        const auto for_each_block = [&](auto&& body) {
            parallel_for_blocks(workers, count, selection_block,
                                [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                                    body(block, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last));
                                });
        };
        // Each worker claims the particles of its own range, reading every
        // candidate: no two threads write one particle, so no claim needs a
        // compare-and-swap, which cost more than the second reading.
        const auto particles = static_cast<std::int64_t>(partner.size());
        parallel_for(workers, workers, [&](std::int64_t worker, std::size_t) {
            const auto low = static_cast<std::uint32_t>(worker * particles / workers);
            const auto span = static_cast<std::uint32_t>((worker + 1) * particles / workers) - low;
            for (std::uint32_t k = 0; k < count; ++k) {
                const Collision& c = candidates[k];
                if (c.i - low < span) claim(c.i, k);
                if (c.kind == CollisionKind::pair && c.j - low < span) claim(c.j, k);
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
        // The candidate first in the order is always accepted, so each round
        // shrinks the list; a round that did not would repeat for ever.
        if (end == candidates.end()) throw std::logic_error("select_collisions: a round accepted no candidate");
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

// Four pairs at once, one in each lane of two exchanges: the same bits as
// one at a time. Each exchange is a long chain of dependent operations; both
// run before either pair is finished, so the processor overlaps them.
void resolve_four_pairs(std::span<PairAtContact, 4> pairs, const Box& box, double duration) {
    ContactPair<TwoDoubles> contacts[2];
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        ContactPair<TwoDoubles>& contact = contacts[k / 2];
        const std::size_t lane = k % 2;
        const Particle(&moved)[2] = pairs[k].moved;
        contact.pix[lane] = moved[0].position.x();
        contact.piy[lane] = moved[0].position.y();
        contact.pjx[lane] = moved[1].position.x();
        contact.pjy[lane] = moved[1].position.y();
        contact.vix[lane] = moved[0].velocity.x();
        contact.viy[lane] = moved[0].velocity.y();
        contact.vjx[lane] = moved[1].velocity.x();
        contact.vjy[lane] = moved[1].velocity.y();
    }
    for (ContactPair<TwoDoubles>& contact : contacts) exchange_normal_components(contact);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const ContactPair<TwoDoubles>& contact = contacts[k / 2];
        const std::size_t lane = k % 2;
        pairs[k].moved[0].velocity = Vec2(contact.vix[lane], contact.viy[lane]);
        pairs[k].moved[1].velocity = Vec2(contact.vjx[lane], contact.vjy[lane]);
        finish_pair(pairs[k], box, duration);
    }
}

}  // namespace

void resolve_collisions(std::span<Particle> particles, std::span<const std::uint32_t> partner,
                        std::span<const double> collision_time, const Box& box, double duration, int threads) {
    constexpr std::int64_t block = 1024;
    constexpr std::size_t pair_lookahead = 16;
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    // In storage order, block by block, reading only per-particle arrays: a
    // large scene is stored by position, so this walks memory instead of
    // jumping through it. A pair is resolved once, at its lower stored
    // index; accepted collisions share no particle, so they resolve
    // independently (and the exchange is symmetric, bit for bit, in its two
    // particles).
    parallel_for_blocks(workers, count, block, [&](std::int64_t, std::int64_t first, std::int64_t last) {
        // The block's collisions are listed first, without a branch on each
        // particle: which ones collide follows no pattern, and a branch on
        // it was mispredicted for most that do.
        std::array<std::uint32_t, block> pair_at;
        std::array<std::uint32_t, block> wall_at;
        std::size_t pairs_listed = 0;
        std::size_t walls_listed = 0;
        for (std::int64_t i = first; i < last; ++i) {
            const std::uint32_t other = partner[i];
            const auto at = static_cast<std::uint32_t>(i);
            pair_at[pairs_listed] = at;
            pairs_listed += static_cast<std::size_t>(other < wall_collision) & static_cast<std::size_t>(at < other);
            wall_at[walls_listed] = at;
            walls_listed += static_cast<std::size_t>(other == wall_collision);
        }
        for (std::size_t k = 0; k < walls_listed; ++k) {
            resolve_wall(particles[wall_at[k]], collision_time[wall_at[k]], box, duration);
        }
        // Pairs wait for three more to share the exchanges. A partner stored
        // a row of cells ahead is a cache miss: it is fetched a few pairs
        // early, both lines a 48-byte particle may span.
        std::array<PairAtContact, 4> pairs;
        std::size_t waiting = 0;
        for (std::size_t k = 0; k < pairs_listed; ++k) {
            if (k + pair_lookahead < pairs_listed) prefetch_lines_of(particles[partner[pair_at[k + pair_lookahead]]]);
            const std::uint32_t i = pair_at[k];
            pairs[waiting++] = at_contact(particles[i], particles[partner[i]], collision_time[i]);
            if (waiting == pairs.size()) {
                resolve_four_pairs(pairs, box, duration);
                waiting = 0;
            }
        }
        for (std::size_t k = 0; k < waiting; ++k) resolve_pair(pairs[k], box, duration);
    });
}

// The same block loop as measure_step_start(), written out: sharing one
// through a callback that hands over the moved particle cost the dense gas
// 2 % (docs/benchmarks.md, tenth session of issue 15).
void advance_free_particles(std::span<Particle> particles, std::span<std::uint32_t> partner, const Box& box,
                            double duration, std::span<double> wall_time, StepStart& next, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    next.resize(particles.size());
    next.with_or_without_motion([&](auto with_motion) {
        parallel_for_blocks(workers, count, motion_block,
                            [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                                BlockStart measured;
                                for (std::int64_t i = first; i < last; ++i) {
                                    // Without a branch on whether the particle collided
                                    // (no pattern to learn): a collided one is stored back
                                    // as it is. Measured on the copy: a position read back
                                    // right after its halves were stored would stall (see
                                    // resolve_wall()).
                                    Particle particle = particles[i];
                                    Particle moved = particle;
                                    move_freely(moved, duration, box);
                                    const bool free = partner[i] == no_collision;
                                    particle.position.x() = free ? moved.position.x() : particle.position.x();
                                    particle.position.y() = free ? moved.position.y() : particle.position.y();
                                    particles[i] = particle;
                                    partner[i] = no_collision;
                                    wall_time[i] = measured.measure<with_motion>(particle, box, duration);
                                }
                                next.blocks[block] = measured;
                            });
    });
    next.measured = true;
}

}  // namespace particlesim
