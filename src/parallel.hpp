#pragma once
// Small OpenMP helpers: how many threads a piece of work deserves, and which
// thread is running. Private to the library.

#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace particlesim {

// Below these amounts a parallel region costs more than it saves.
inline constexpr std::int64_t min_particles_per_thread = 2048;
inline constexpr std::int64_t min_pair_work_per_thread = 4096;

inline int worker_count(std::size_t available, std::int64_t work, std::int64_t min_work_per_thread) {
    const std::int64_t useful = std::max<std::int64_t>(1, work / min_work_per_thread);
    return static_cast<int>(std::min<std::int64_t>(static_cast<std::int64_t>(available), useful));
}

inline std::size_t current_thread() { return static_cast<std::size_t>(omp_get_thread_num()); }

}  // namespace particlesim
