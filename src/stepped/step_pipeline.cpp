#include "stepped/step_pipeline.hpp"

#include "core/assert.hpp"
#include "core/motion_lanes.hpp"
#include "core/physics.hpp"
#include "core/prefetch.hpp"
#include "parallel/parallel.hpp"
#include "stepped/collided_lists.hpp"
#include "stepped/free_flight_lanes.hpp"
#include "stepped/stepped_tuning.hpp"
#include "stepped/wall_bounce_lanes.hpp"
#include "stepped/wall_candidate_lanes.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <stdexcept>

namespace particlesim {

using namespace stepped_tuning;

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
        const std::size_t end = at + start.blocks[block].wall_candidates;
        const WallCandidatesWritten in_lanes =
            write_wall_candidates_in_lanes(wall_time.data(), duration, first, last, candidates.data() + at, end - at);
        at += in_lanes.written;
        // The rest without a branch on which particles hit a wall (a
        // quarter of them in sparse scenes, at random): every particle is
        // written to the next free place, which only a hit keeps; the place
        // past the block's last is never written (another block's, or none).
        for (std::int64_t i = in_lanes.next; i < last && at < end; ++i) {
            candidates[at] = Collision::wall(wall_time[i], static_cast<std::uint32_t>(i));
            at += static_cast<std::size_t>(wall_time[i] <= duration);
        }
    });
}

namespace {

// One round of the selection: every candidate that comes first among all
// candidates of its particles is accepted, and it and every candidate it
// rules out leave the list. Each step of the round is a parallel pass.
class SelectionRound {
public:
    SelectionRound(std::vector<Collision>& candidates, const CandidateOrder& order, std::span<std::uint32_t> partner,
                   std::span<double> collision_time, SelectionScratch& scratch, int threads)
        : candidates_(candidates),
          order_(order),
          partner_(partner),
          collision_time_(collision_time),
          scratch_(scratch),
          earliest_(scratch.earliest),
          count_(static_cast<std::int64_t>(candidates.size())),
          blocks_((count_ + selection_block - 1) / selection_block),
          workers_(worker_count(static_cast<std::size_t>(threads), count_, min_particles_per_thread)) {}

    // Each particle's earliest candidate in the order, in `earliest`. Each
    // worker claims the particles of its own range, reading every
    // candidate: no two threads write one particle, so no claim needs a
    // compare-and-swap, which cost more than the second reading.
    void claim_earliest() {
        const auto particles = static_cast<std::int64_t>(partner_.size());
        parallel_for(workers_, workers_, [&](std::int64_t worker, std::size_t) {
            const auto low = static_cast<std::uint32_t>(worker * particles / workers_);
            const auto span = static_cast<std::uint32_t>((worker + 1) * particles / workers_) - low;
            for (std::uint32_t k = 0; k < count_; ++k) {
                const Collision& c = candidates_[k];
                if (c.i - low < span) claim(c.i, k);
                if (c.kind == CollisionKind::pair && c.j - low < span) claim(c.j, k);
            }
        });
    }

    // Accepts every candidate that all its particles claimed. Accepted
    // collisions share no particle: each thread writes its own. Partners
    // are written atomically: the grid search may read them meanwhile on
    // another thread (SliceDecisions::decided()).
    StepCounts accept_claimed() {
        scratch_.block_counts.resize(static_cast<std::size_t>(blocks_));
        for_each_block([&](std::int64_t block, std::uint32_t first, std::uint32_t last) {
            StepCounts& accepted = scratch_.block_counts[block];
            accepted = {};
            for (std::uint32_t k = first; k < last; ++k) {
                const Collision& c = candidates_[k];
                if (earliest_[c.i] != k) continue;
                if (c.kind == CollisionKind::wall) {
                    PARTICLESIM_ASSERT(partner_[c.i] == no_collision, "no particle has two collisions selected");
                    set_partner(c.i, wall_collision);
                    collision_time_[c.i] = c.time;
                    ++accepted.wall_collisions;
                } else if (earliest_[c.j] == k) {
                    PARTICLESIM_ASSERT(partner_[c.i] == no_collision && partner_[c.j] == no_collision,
                                       "no particle has two collisions selected");
                    set_partner(c.i, c.j);
                    set_partner(c.j, c.i);
                    collision_time_[c.i] = c.time;
                    collision_time_[c.j] = c.time;
                    ++accepted.particle_collisions;
                }
            }
        });
        StepCounts counts;
        for (const StepCounts& accepted : scratch_.block_counts) counts += accepted;
        return counts;
    }

    // Clears the claims for the next round (only the claimed particles).
    void release_claims() {
        for_each_block([&](std::int64_t, std::uint32_t first, std::uint32_t last) {
            for (std::uint32_t k = first; k < last; ++k) {
                const Collision& c = candidates_[k];
                std::atomic_ref<std::uint32_t>(earliest_[c.i]).store(no_collision, std::memory_order_relaxed);
                if (c.kind == CollisionKind::pair) {
                    std::atomic_ref<std::uint32_t>(earliest_[c.j]).store(no_collision, std::memory_order_relaxed);
                }
            }
        });
    }

    // Accepted candidates and those they rule out leave; the rest go on, in
    // their order: each block keeps its own, then they close up.
    void keep_undecided() {
        scratch_.block_kept.resize(static_cast<std::size_t>(blocks_));
        for_each_block([&](std::int64_t block, std::uint32_t first, std::uint32_t last) {
            const auto begin = candidates_.begin() + first;
            const auto kept = std::remove_if(begin, candidates_.begin() + last,
                                             [&](const Collision& c) { return !undecided(c, partner_); });
            scratch_.block_kept[block] = static_cast<std::uint32_t>(kept - begin);
        });
        auto end = candidates_.begin();
        for (std::int64_t block = 0; block < blocks_; ++block) {
            const auto begin = candidates_.begin() + block * selection_block;
            const auto kept_end = begin + scratch_.block_kept[block];
            // A block with nothing dropped before it is in place already.
            end = end == begin ? kept_end : std::move(begin, kept_end, end);
        }
        // The candidate first in the order is always accepted, so each round
        // shrinks the list; a round that did not would repeat for ever.
        if (end == candidates_.end()) throw std::logic_error("select_collisions: a round accepted no candidate");
        candidates_.erase(end, candidates_.end());
    }

private:
    void set_partner(std::uint32_t particle, std::uint32_t partner) {
        std::atomic_ref<std::uint32_t>(partner_[particle]).store(partner, std::memory_order_relaxed);
    }

    // A pair found twice is two equal candidates: the first in place counts,
    // so that every thread count picks the same one.
    bool comes_first(std::uint32_t k, std::uint32_t other) const {
        return order_.before(candidates_[k], candidates_[other]) ||
               (k < other && !order_.before(candidates_[other], candidates_[k]));
    }

    // Whether candidate k comes before the one a particle holds (or it
    // holds none). Without branches on either: which way it goes follows no
    // pattern. Times decide all but ties, which take the full order.
    bool takes_over(std::uint32_t k, std::uint32_t held) const {
        const bool none = held == no_collision;
        const double time = candidates_[k].time;
        const double held_time = candidates_[none ? k : held].time;
        const bool tie = !none & (time == held_time);
        if (tie) [[unlikely]]
            return comes_first(k, held);
        return none | (time < held_time);
    }

    void claim(std::uint32_t particle, std::uint32_t k) {
        std::uint32_t& held = earliest_[particle];
        held = takes_over(k, held) ? k : held;
    }

    template <typename Body>
    void for_each_block(Body&& body) {
        parallel_for_blocks(workers_, count_, selection_block,
                            [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                                body(block, static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last));
                            });
    }

    std::vector<Collision>& candidates_;
    const CandidateOrder& order_;
    std::span<std::uint32_t> partner_;
    std::span<double> collision_time_;
    SelectionScratch& scratch_;
    std::span<std::uint32_t> earliest_;
    std::int64_t count_;
    std::int64_t blocks_;
    int workers_;
};

// The rest of the selection in one walk of the candidates sorted in the
// order: the greedy pass itself. Partners are written atomically, as the
// rounds write them.
StepCounts select_in_order(std::vector<Collision>& candidates, const CandidateOrder& order,
                           std::span<std::uint32_t> partner, std::span<double> collision_time) {
    std::sort(candidates.begin(), candidates.end(),
              [&](const Collision& a, const Collision& b) { return order.before(a, b); });
    const auto set_partner = [&](std::uint32_t particle, std::uint32_t other) {
        std::atomic_ref<std::uint32_t>(partner[particle]).store(other, std::memory_order_relaxed);
    };
    StepCounts counts;
    for (const Collision& c : candidates) {
        if (!undecided(c, partner)) continue;
        collision_time[c.i] = c.time;
        if (c.kind == CollisionKind::wall) {
            set_partner(c.i, wall_collision);
            ++counts.wall_collisions;
        } else {
            set_partner(c.i, c.j);
            set_partner(c.j, c.i);
            collision_time[c.j] = c.time;
            ++counts.particle_collisions;
        }
    }
    candidates.clear();
    return counts;
}

}  // namespace

StepCounts select_collisions(std::vector<Collision>& candidates, std::span<const ThreadCandidates> found,
                             const CandidateOrder& order, std::span<std::uint32_t> partner,
                             std::span<double> collision_time, SelectionScratch& scratch, int threads) {
    for (const ThreadCandidates& thread : found) {
        candidates.insert(candidates.end(), thread.found.begin(), thread.found.end());
    }
    StepCounts counts;
    while (!candidates.empty()) {
        const std::size_t before = candidates.size();
        SelectionRound round(candidates, order, partner, collision_time, scratch, threads);
        round.claim_earliest();
        counts += round.accept_claimed();
        round.release_claims();
        round.keep_undecided();
        if (selection_stalled(before, candidates.size())) {
            counts += select_in_order(candidates, order, partner, collision_time);
            break;
        }
    }
    return counts;
}

namespace {

// Both work on copies in registers and store each particle once: reading a
// coordinate pair back from memory right after storing its halves one by one
// stalls the processor (the load cannot be served from the pending stores).

void resolve_wall(Particle& particle, double time, const Box& box, double duration) {
    Particle moved = particle;
    MotionLanes motion(moved, box);
    // Recomputed from the unchanged start state, so it equals the candidate.
    motion.bounce();
    motion.move_stopping_at_wall(duration - time);
    moved.position = motion.position();
    moved.velocity = motion.velocity();
    ++moved.wall_collisions;
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
        MotionLanes motion(p, box);
        motion.move_stopping_at_wall(duration - pair.time);
        p.position = motion.position();
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
                        std::span<const double> collision_time, const StepCounts& accepted, const Box& box,
                        double duration, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const auto collided = static_cast<std::int64_t>(2 * accepted.particle_collisions + accepted.wall_collisions);
    const int workers =
        std::min(worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread),
                 worker_count(static_cast<std::size_t>(threads), collided, resolution_collided_per_thread));
    // In storage order, block by block, reading only per-particle arrays: a
    // large scene is stored by position, so this walks memory instead of
    // jumping through it. A pair is resolved once, at its lower stored
    // index; accepted collisions share no particle, so they resolve
    // independently (and the exchange is symmetric, bit for bit, in its two
    // particles).
    parallel_for_blocks(workers, count, resolution_block, [&](std::int64_t, std::int64_t first, std::int64_t last) {
        // The block's collisions are listed first.
        std::array<std::uint32_t, resolution_block + collided_lists_spill> pair_at;
        std::array<std::uint32_t, resolution_block + collided_lists_spill> wall_at;
        const CollidedCounts listed = list_collided(partner.data(), first, last, pair_at.data(), wall_at.data());
        const std::size_t pairs_listed = listed.pairs;
        const std::size_t walls_listed = listed.walls;
        const std::size_t walls_in_lanes = resolve_walls_four_at_a_time(particles.data(), wall_at.data(), walls_listed,
                                                                        collision_time.data(), box, duration);
        for (std::size_t k = walls_in_lanes; k < walls_listed; ++k) {
            resolve_wall(particles[wall_at[k]], collision_time[wall_at[k]], box, duration);
        }
        // Pairs wait for three more to share the exchanges. A partner stored
        // a row of cells ahead is a cache miss: it is fetched a few pairs
        // early, both lines a 48-byte particle may span.
        std::array<PairAtContact, 4> pairs;
        std::size_t waiting = 0;
        for (std::size_t k = 0; k < pairs_listed; ++k) {
            if (k + resolution_fetch_ahead < pairs_listed)
                prefetch_lines_of(particles[partner[pair_at[k + resolution_fetch_ahead]]]);
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
// through a callback that hands over the moved particle was slower
// (docs/benchmarks.md, "Tried, measured, not kept").
void advance_free_particles(std::span<Particle> particles, std::span<std::uint32_t> partner, const Box& box,
                            double duration, std::span<double> wall_time, StepStart& next, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    next.resize(particles.size());
    next.with_or_without_motion([&](auto with_motion) {
        parallel_for_blocks(
            workers, count, motion_block, [&](std::int64_t block, std::int64_t first, std::int64_t last) {
                // In locals: else the compiler must assume that the
                // stores below may change the spans and the box, and
                // reads them again for every particle.
                Particle* const stored = particles.data();
                std::uint32_t* const partners = partner.data();
                double* const times = wall_time.data();
                const Box in = box;
                const double step = duration;
                BlockStart measured;
                // Four at a time where the processor has the lanes; not
                // where the motion is summed, whose sums must add up in
                // the particles' order.
                std::int64_t i = first;
                if constexpr (!with_motion) {
                    i = fly_four_at_a_time(stored, partners, times, in, step, first, last, measured.wall_candidates);
                }
                for (; i < last; ++i) {
                    // Without a branch on whether the particle collided
                    // (no pattern to learn; the compiler turned a select,
                    // and a product by 0 or 1, into one): a collided one,
                    // resolved already, moves for +0.0, which changes no
                    // bit of a position inside the box. In two lanes, and
                    // measured on them: a position read back right after
                    // its halves were stored would stall (see resolve_wall()).
                    Particle particle = stored[i];
                    const std::uint64_t free = -static_cast<std::uint64_t>(partners[i] == no_collision);
                    const double flight = std::bit_cast<double>(std::bit_cast<std::uint64_t>(step) & free);
                    MotionLanes motion(particle, in);
                    motion.fly(flight);
                    particle.position = motion.position();
                    stored[i] = particle;
                    partners[i] = no_collision;
                    times[i] = measured.count<with_motion>(particle.velocity, motion.wall_time(), step);
                }
                next.blocks[block] = measured;
            });
    });
    next.measured = true;
}

}  // namespace particlesim
