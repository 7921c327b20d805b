#include "step_pipeline.hpp"

#include "parallel.hpp"
#include "physics.hpp"

#include <algorithm>
#include <array>

namespace particlesim {

void detect_wall_candidates(std::span<const Particle> particles, const Box& box, double duration,
                            std::span<double> wall_time, std::vector<Collision>& candidates, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    parallel_for(workers, count, [&](std::int64_t i, std::size_t) {
        wall_time[i] = time_to_wall(particles[i].position, particles[i].velocity, box).time;
    });
    for (std::int64_t i = 0; i < count; ++i) {
        if (wall_time[i] <= duration)
            candidates.push_back(Collision::wall(wall_time[i], static_cast<std::uint32_t>(i)));
    }
}

namespace {

// Candidates sorted by stored indices are in the total order except within
// runs of equal (t, kind), where the user's indices decide: such a run is
// renamed to user indices, sorted, and renamed back.
void order_ties_by_user_index(std::span<Collision> sorted, std::span<const std::uint32_t> user_index,
                              std::span<const std::uint32_t> stored_index) {
    const auto rename = [](std::span<Collision> run, std::span<const std::uint32_t> index) {
        for (Collision& c : run) {
            c.i = index[c.i];
            if (c.kind == CollisionKind::pair) {
                c.j = index[c.j];
                if (c.i > c.j) std::swap(c.i, c.j);
            }
        }
    };
    for (std::size_t first = 0; first < sorted.size();) {
        std::size_t last = first + 1;
        while (last < sorted.size() && sorted[last].time == sorted[first].time &&
               sorted[last].kind == sorted[first].kind) {
            ++last;
        }
        if (last - first > 1) {
            const std::span<Collision> run = sorted.subspan(first, last - first);
            rename(run, user_index);
            std::sort(run.begin(), run.end());
            rename(run, stored_index);
        }
        first = last;
    }
}

}  // namespace

void order_candidates(std::vector<Collision>& candidates, std::span<ThreadCandidates> found,
                      std::vector<Collision>& scratch, std::span<const std::uint32_t> user_index,
                      std::span<const std::uint32_t> stored_index, int threads) {
    std::int64_t count = static_cast<std::int64_t>(candidates.size());
    for (const ThreadCandidates& thread : found) count += static_cast<std::int64_t>(thread.found.size());
    // The merge keeps one cursor per list on the stack.
    constexpr std::size_t max_merged_lists = 17;
    const int workers = found.size() + 1 <= max_merged_lists
                            ? worker_count(static_cast<std::size_t>(threads), count, min_candidates_per_thread)
                            : 1;
    if (workers <= 1) {
        for (const ThreadCandidates& thread : found) {
            candidates.insert(candidates.end(), thread.found.begin(), thread.found.end());
        }
        std::sort(candidates.begin(), candidates.end());
    } else {
        // Busy steps: the walls (moved to `scratch`) and each thread's list are
        // sorted on several threads, then merged into `candidates`. No list
        // is copied whole, so the memory stays that of the lists themselves.
        scratch.assign(candidates.begin(), candidates.end());
        const auto list = [&](std::size_t k) -> std::vector<Collision>& {
            return k == 0 ? scratch : found[k - 1].found;
        };
        const std::size_t lists = found.size() + 1;
        parallel_for_dynamic(workers, static_cast<std::int64_t>(lists), 1, [&](std::int64_t k, std::size_t) {
            std::sort(list(static_cast<std::size_t>(k)).begin(), list(static_cast<std::size_t>(k)).end());
        });
        candidates.clear();
        std::array<std::size_t, max_merged_lists> heads{};
        while (true) {
            std::size_t best = lists;
            for (std::size_t k = 0; k < lists; ++k) {
                if (heads[k] < list(k).size() && (best == lists || list(k)[heads[k]] < list(best)[heads[best]]))
                    best = k;
            }
            if (best == lists) break;
            candidates.push_back(list(best)[heads[best]++]);
        }
    }
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    if (!user_index.empty()) order_ties_by_user_index(candidates, user_index, stored_index);
}

void select_collisions(std::span<const Collision> ordered, std::span<std::uint32_t> collision_of,
                       std::vector<Collision>& accepted) {
    accepted.clear();
    for (const Collision& c : ordered) {
        if (collision_of[c.i] != 0) continue;
        if (c.kind == CollisionKind::pair && collision_of[c.j] != 0) continue;
        accepted.push_back(c);
        const auto number = static_cast<std::uint32_t>(accepted.size());
        collision_of[c.i] = number;
        if (c.kind == CollisionKind::pair) collision_of[c.j] = number;
    }
}

namespace {

void resolve_wall(Particle& particle, double time, const Box& box, double duration) {
    // Recomputed from the unchanged start state, so it equals the candidate.
    const WallHit hit = time_to_wall(particle.position, particle.velocity, box);
    bounce_off_wall(particle, hit, box);
    move_stopping_at_wall(particle, duration - time, box);
}

void resolve_pair(Particle& a, Particle& b, double time, const Box& box, double duration) {
    a.position += a.velocity * time;
    b.position += b.velocity * time;
    exchange_normal_velocities(a.position, b.position, a.velocity, b.velocity);
    for (Particle* p : {&a, &b}) {
        ++p->particle_collisions;
        clamp_into_box(p->position, box);
        move_stopping_at_wall(*p, duration - time, box);
    }
}

}  // namespace

void resolve_collisions(std::span<Particle> particles, std::span<const std::uint32_t> collision_of,
                        std::span<const Collision> accepted, const Box& box, double duration, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    // In storage order, not in the accepted (time) order: a large scene is
    // stored by position, so this walks memory instead of jumping through it.
    // A pair is resolved once, at its particle c.i; accepted collisions share
    // no particle, so they resolve independently.
    parallel_for(workers, count, [&](std::int64_t i, std::size_t) {
        if (collision_of[i] == 0) return;
        const Collision& c = accepted[collision_of[i] - 1];
        if (c.kind == CollisionKind::wall) {
            resolve_wall(particles[i], c.time, box, duration);
        } else if (c.i == static_cast<std::uint32_t>(i)) {
            resolve_pair(particles[c.i], particles[c.j], c.time, box, duration);
        }
    });
}

void advance_free_particles(std::span<Particle> particles, std::span<std::uint32_t> collision_of, const Box& box,
                            double duration, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    parallel_for(workers, count, [&](std::int64_t i, std::size_t) {
        if (collision_of[i] == 0) {
            move_freely(particles[i], duration, box);
        } else {
            collision_of[i] = 0;
        }
    });
}

}  // namespace particlesim
