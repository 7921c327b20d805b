#include "parallel/parallel.hpp"
#include "particlesim/stepped_simulation.hpp"

#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace particlesim {

namespace {

// The parallel regions this process has opened, and whether it is a child
// forked after its parent had opened one (its OpenMP threads stayed behind).
std::atomic<std::uint64_t> regions_opened{0};
std::atomic<bool> forked_after_regions{false};

// Registered once, before the first loop can run.
const bool fork_watch = [] {
    pthread_atfork(nullptr, nullptr, [] { forked_after_regions.store(regions_opened.load() > 0); });
    return true;
}();

}  // namespace

// OMP_NUM_THREADS may ask for more than an engine takes (max_threads).
int default_thread_count() {
    return omp_get_active_level() > 0 ? 1 : std::clamp(omp_get_max_threads(), 1, max_threads);
}

bool loops_may_start_threads() {
    if (omp_get_active_level() > 0 || forked_after_regions.load(std::memory_order_relaxed)) return false;
    regions_opened.fetch_add(1, std::memory_order_relaxed);
    return true;
}

std::uint64_t parallel_regions_opened() { return regions_opened.load(std::memory_order_relaxed); }

}  // namespace particlesim
