#include "particlesim/step_pipeline.hpp"

#include "parallel.hpp"
#include "particlesim/physics.hpp"

#include <algorithm>

namespace particlesim {

void detect_wall_candidates(std::span<const Particle> particles, const Box& box, double duration,
                            std::span<double> wall_time, std::vector<Collision>& candidates, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    parallel_for(workers, count, [&](std::int64_t i, std::size_t) {
        wall_time[i] = time_to_wall(particles[i].position, particles[i].velocity, box).time;
    });
    for (std::int64_t i = 0; i < count; ++i) {
        if (wall_time[i] <= duration) candidates.push_back(Collision::wall(wall_time[i], static_cast<std::uint32_t>(i)));
    }
}

void order_candidates(std::vector<Collision>& candidates, std::span<ThreadCandidates> found,
                      std::vector<Collision>& scratch, int threads) {
    for (ThreadCandidates& thread : found) {
        candidates.insert(candidates.end(), thread.found.begin(), thread.found.end());
    }
    const auto count = static_cast<std::int64_t>(candidates.size());
    if (count < 2) return;
    // Busy steps: each worker sorts a part, then the parts are merged in
    // pairs. The total order makes the result the same as one sort.
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_candidates_per_thread);
    const auto part_start = [&](std::int64_t part) { return candidates.begin() + part * count / workers; };
    parallel_for(workers, workers, [&](std::int64_t part, std::size_t) {
        std::sort(part_start(part), part_start(part + 1));
    });
    for (int width = 1; width < workers; width *= 2) {
        scratch.resize(candidates.size());
        for (int first = 0; first < workers; first += 2 * width) {
            const int middle = std::min(first + width, workers);
            const int last = std::min(first + 2 * width, workers);
            std::merge(part_start(first), part_start(middle), part_start(middle), part_start(last),
                       scratch.begin() + (part_start(first) - candidates.begin()));
        }
        candidates.swap(scratch);
    }
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
}

void select_collisions(std::span<const Collision> ordered, std::span<std::uint8_t> busy,
                       std::vector<Collision>& accepted) {
    accepted.clear();
    for (const Collision& c : ordered) {
        if (busy[c.i]) continue;
        if (c.kind == CollisionKind::pair) {
            if (busy[c.j]) continue;
            busy[c.j] = 1;
        }
        busy[c.i] = 1;
        accepted.push_back(c);
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

void resolve_collisions(std::span<Particle> particles, std::span<const Collision> accepted, const Box& box,
                        double duration, int threads) {
    const auto count = static_cast<std::int64_t>(accepted.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    // Accepted collisions share no particle, so they resolve independently.
    parallel_for(workers, count, [&](std::int64_t k, std::size_t) {
        const Collision& c = accepted[k];
        if (c.kind == CollisionKind::wall) {
            resolve_wall(particles[c.i], c.time, box, duration);
        } else {
            resolve_pair(particles[c.i], particles[c.j], c.time, box, duration);
        }
    });
}

void advance_free_particles(std::span<Particle> particles, std::span<std::uint8_t> busy,
                            std::span<const Collision> accepted, const Box& box, double duration, int threads) {
    const auto count = static_cast<std::int64_t>(particles.size());
    const int workers = worker_count(static_cast<std::size_t>(threads), count, min_particles_per_thread);
    parallel_for(workers, count, [&](std::int64_t i, std::size_t) {
        if (!busy[i]) move_freely(particles[i], duration, box);
    });
    for (const Collision& c : accepted) {
        busy[c.i] = 0;
        if (c.kind == CollisionKind::pair) busy[c.j] = 0;
    }
}

}  // namespace particlesim
