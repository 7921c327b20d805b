#pragma once
// Parallel loops on OpenMP, and how many threads a piece of work deserves.
// One thread runs the loop in place, without a parallel region.
//
// A loop hands its items out in chunks, claimed by whichever thread is
// free: a thread the system deschedules, on a machine where another process
// keeps a core busy, delays only the chunk it holds, not a share of the
// items that the others would wait for at the barrier. Where the items'
// data stays from one step to the next (particles sorted by position, the
// grid's rows), each thread first claims from a contiguous share of its
// own, the same share at every step, so that the data stays in its core's
// caches (handed to whichever thread is free, it would cross between the
// cores at every step). How idle threads wait between regions is the
// OpenMP runtime's (OMP_WAIT_POLICY, README "Threads").

#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <utility>

namespace particlesim {

// Below these amounts a parallel loop costs more than it saves.
inline constexpr std::int64_t min_particles_per_thread = 2048;
inline constexpr std::int64_t min_pair_work_per_thread = 4096;

// Threads when none are asked for: OpenMP's default (OMP_NUM_THREADS, else
// the cores this process may use); 1 inside a parallel region of the caller's.
int default_thread_count();

// Whether a loop may start threads here: not inside a parallel region of the
// caller's (the library then runs on the thread it is given instead of
// oversubscribing the machine), and not in a child forked from this process
// after it ran a parallel loop (libgomp's threads do not survive a fork, and
// its next region would wait for them for ever). Called by a loop about to
// open a region, which it then counts.
bool loops_may_start_threads();

// The parallel regions the loops have opened in this process: how a test
// tells that work ran on one thread, whatever the threads asked for.
std::uint64_t parallel_regions_opened();

inline int worker_count(std::size_t available, std::int64_t work, std::int64_t min_work_per_thread) {
    const std::int64_t useful = std::max<std::int64_t>(1, work / min_work_per_thread);
    return static_cast<int>(std::min<std::int64_t>(static_cast<std::int64_t>(available), useful));
}

namespace detail {

// One thread's share of a loop: the items [next, end) not yet claimed.
// A cache line each: the owner claims from it at every chunk.
struct alignas(64) LoopShare {
    std::atomic<std::int64_t> next{0};
    std::int64_t end = 0;
};

// A region of more threads than this shares them out: thread t starts on
// share t modulo this.
inline constexpr int max_loop_shares = 64;

// body(i, thread) for i in [0, count) on `workers` threads (thread <
// workers), the items cut into `shares` contiguous shares (at most
// max_loop_shares) claimed `chunk` items at a time: thread t from share t
// first, then from the others. What the body throws (std::bad_alloc: a list
// of pair candidates past its limit) is caught in the region, which an
// exception may not leave (std::terminate), and the first one is thrown
// again on the calling thread once the region ends; the other items still
// run (a check before each would cost every loop for a failure that ends
// the run).
template <typename Body>
void loop_in_shares(int workers, std::int64_t count, std::int64_t chunk, int shares, Body&& body) {
    if (workers <= 1 || count <= chunk || !loops_may_start_threads()) {
        for (std::int64_t i = 0; i < count; ++i) body(i, std::size_t{0});
        return;
    }
    shares = std::clamp(shares, 1, max_loop_shares);
    std::array<LoopShare, max_loop_shares> share;
    for (int s = 0; s < shares; ++s) {
        share[s].next.store(count * s / shares, std::memory_order_relaxed);
        share[s].end = count * (s + 1) / shares;
    }
    std::exception_ptr failure;
    // A team smaller than asked for still runs every item: each thread goes
    // round all the shares until none is left.
#pragma omp parallel num_threads(workers)
    {
        const int thread = omp_get_thread_num();
        for (int k = 0; k < shares; ++k) {
            LoopShare& from = share[(thread + k) % shares];
            for (;;) {
                const std::int64_t first = from.next.fetch_add(chunk, std::memory_order_relaxed);
                if (first >= from.end) break;
                const std::int64_t last = std::min(from.end, first + chunk);
                for (std::int64_t i = first; i < last; ++i) {
                    try {
                        body(i, static_cast<std::size_t>(thread));
                    } catch (...) {
#pragma omp critical(particlesim_parallel_failure)
                        if (!failure) failure = std::current_exception();
                    }
                }
            }
        }
    }
    if (failure) std::rethrow_exception(failure);
}

}  // namespace detail

// body(i, thread) for i in [0, count), in chunks of `chunk` items claimed by
// whichever of the `workers` threads is free (thread < workers): for items
// whose work differs and whose data no thread had before, such as the
// grid's slices.
template <typename Body>
void parallel_for_dynamic(int workers, std::int64_t count, std::int64_t chunk, Body&& body) {
    detail::loop_in_shares(workers, count, chunk, 1, std::forward<Body>(body));
}

// The same, each thread starting with a contiguous share of its own, the
// same share at every call of the same count: for items whose data stays in
// a core's caches from one step to the next, such as particles sorted by
// position and the grid's rows of cells.
template <typename Body>
void parallel_for_in_shares(int workers, std::int64_t count, std::int64_t chunk, Body&& body) {
    detail::loop_in_shares(workers, count, chunk, workers, std::forward<Body>(body));
}

// The same for items of even work, such as particles: claimed in eight
// chunks a share, so that a thread the system deschedules leaves the rest
// of its share to the others.
template <typename Body>
void parallel_for(int workers, std::int64_t count, Body&& body) {
    const std::int64_t chunk = std::max<std::int64_t>(1, count / (8 * std::max(workers, 1)));
    parallel_for_in_shares(workers, count, chunk, std::forward<Body>(body));
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
