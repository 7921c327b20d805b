#pragma once
// Small OpenMP helpers: how many threads a piece of work deserves, and loops
// that run without touching OpenMP at all when one thread is enough (even an
// `if (false)` parallel region costs a team allocation and futex calls).

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace particlesim {

// Below these amounts a parallel region costs more than it saves.
inline constexpr std::int64_t min_particles_per_thread = 2048;
inline constexpr std::int64_t min_pair_work_per_thread = 4096;
inline constexpr std::int64_t min_candidates_per_thread = 16384;

inline int worker_count(std::size_t available, std::int64_t work, std::int64_t min_work_per_thread) {
    const std::int64_t useful = std::max<std::int64_t>(1, work / min_work_per_thread);
    return static_cast<int>(std::min<std::int64_t>(static_cast<std::int64_t>(available), useful));
}

inline std::size_t current_thread() { return static_cast<std::size_t>(omp_get_thread_num()); }

// body(i, thread) for i in [0, count): static schedule (even work per item).
template <typename Body>
void parallel_for(int workers, std::int64_t count, Body&& body) {
    if (workers <= 1) {
        for (std::int64_t i = 0; i < count; ++i) body(i, std::size_t{0});
        return;
    }
#pragma omp parallel for schedule(static) num_threads(workers)
    for (std::int64_t i = 0; i < count; ++i) body(i, current_thread());
}

// The same with a dynamic schedule, for items of uneven work.
template <typename Body>
void parallel_for_dynamic(int workers, std::int64_t count, int chunk, Body&& body) {
    if (workers <= 1) {
        for (std::int64_t i = 0; i < count; ++i) body(i, std::size_t{0});
        return;
    }
#pragma omp parallel for schedule(dynamic, chunk) num_threads(workers)
    for (std::int64_t i = 0; i < count; ++i) body(i, current_thread());
}

}  // namespace particlesim
