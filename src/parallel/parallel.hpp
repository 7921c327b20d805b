#pragma once
// Parallel loops over the library's thread team (thread_team.hpp), and how
// many threads a piece of work deserves. One thread runs the loop in place.

#include "parallel/thread_team.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>

namespace particlesim {

// Below these amounts a parallel loop costs more than it saves.
inline constexpr std::int64_t min_particles_per_thread = 2048;
inline constexpr std::int64_t min_pair_work_per_thread = 4096;

// Threads when none are asked for: OpenMP's default (OMP_NUM_THREADS, else the cores this process may use).
int default_thread_count();

inline int worker_count(std::size_t available, std::int64_t work, std::int64_t min_work_per_thread) {
    const std::int64_t useful = std::max<std::int64_t>(1, work / min_work_per_thread);
    return static_cast<int>(std::min<std::int64_t>(static_cast<std::int64_t>(available), useful));
}

// body(i, thread) for i in [0, count), in chunks of `chunk` items claimed by
// whichever of the `workers` threads is free (thread < workers).
template <typename Body>
void parallel_for_dynamic(int workers, std::int64_t count, std::int64_t chunk, Body&& body) {
    if (workers <= 1) {
        for (std::int64_t i = 0; i < count; ++i) body(i, std::size_t{0});
        return;
    }
    using Stored = std::remove_reference_t<Body>;
    const auto run_chunk = [](void* context, std::int64_t first, std::int64_t last, std::size_t thread) {
        Stored& stored = *static_cast<Stored*>(context);
        for (std::int64_t i = first; i < last; ++i) stored(i, thread);
    };
    ThreadTeam::shared().run(workers, count, chunk, run_chunk,
                             const_cast<void*>(static_cast<const void*>(std::addressof(body))));
}

// The same for items of even work: eight chunks per thread, so that a thread
// the system deschedules leaves its share to the others.
template <typename Body>
void parallel_for(int workers, std::int64_t count, Body&& body) {
    const std::int64_t chunk = std::max<std::int64_t>(1, count / (8 * std::max(workers, 1)));
    parallel_for_dynamic(workers, count, chunk, std::forward<Body>(body));
}

// body(block, first, last) for the blocks [first, last) of `block_size`
// items that cover [0, count) (the last one may be shorter), shared by
// `workers` threads.
template <typename Body>
void parallel_for_blocks(int workers, std::int64_t count, std::int64_t block_size, Body&& body) {
    parallel_for(workers, (count + block_size - 1) / block_size, [&](std::int64_t block, std::size_t) {
        body(block, block * block_size, std::min(count, (block + 1) * block_size));
    });
}

// The same in at most `ranges` blocks of equal size: for loops that count
// in one pass and write in a second, where each range writes from the sum
// of the counts of the ranges before it.
template <typename Body>
void parallel_for_ranges(int workers, std::int64_t count, std::int64_t ranges, Body&& body) {
    parallel_for_blocks(workers, count, std::max<std::int64_t>(1, (count + ranges - 1) / ranges),
                        std::forward<Body>(body));
}

}  // namespace particlesim
